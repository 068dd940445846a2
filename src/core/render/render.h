/* render.h — rendering a scene into a film: the Embree scene, the lights and the camera are set
 * up, then tiles of 16x16 pixels are handed to worker threads from one atomic counter. Every
 * pixel is computed wholly by one thread from samples keyed by the pixel, so the film is
 * bit-identical for any thread count. */
#ifndef SYLVA_RENDER_H
#define SYLVA_RENDER_H

#include "render/film.h"
#include "scene/scene.h"

typedef struct render_options {
    unsigned threads;   /* 0: one per core */
    int verify;         /* verification mode (see integrator.h) */
    int flat_earth;     /* 1: straight camera rays even when the scene's earth.curvature is on */
    int quiet;          /* no progress output */
    uint32_t spp;       /* 0: the scene's */
    uint32_t width, height; /* 0: the scene's */
    int seed_set;
    uint64_t seed;
    const struct ray_recorder *recorder; /* benchmarks: sees every ray; forces one thread */
} render_options;

typedef struct render_stats {
    double build_seconds;   /* BVH build */
    double render_seconds;  /* pixels */
    uint64_t samples;
} render_stats;

/* Renders s; returns a new film (film_free) or NULL with err set. stats may be NULL. */
film *render_scene(const scene *s, const render_options *opt, render_stats *stats, err_buf *err);

unsigned render_default_threads(void);

#endif
