/* render.h — rendering a scene into a film: the Embree scene, the lights and the camera are set
 * up, then tiles of 16x16 pixels are handed to worker threads from one atomic counter. Every
 * pixel is computed wholly by one thread from samples keyed by the pixel, so the film is
 * bit-identical for any thread count. A render can be one part of several (the ranks of an MPI
 * job, docs/mpi.md): it computes only its bands of rows, and the same pixels come out as from
 * the whole. */
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
    unsigned leave_out; /* ACCEL_MASK_* bits (render/accel.h): geometry that no ray meets, as if
                         * it were not in the scene; 0: none. ACCEL_MASK_DEVELOPMENT renders the
                         * scene without its development, with the same samples as the whole */
    uint32_t part, parts; /* parts > 1: render only the bands of RENDER_BAND_ROWS rows whose
                           * index modulo parts is part (band k holds rows [16 k, 16 k + 16));
                           * the other pixels are left zero. 0 or 1: every pixel */
    struct lights_cache *lights; /* render_setup_new: the lights taken from this cache
                                  * (render/lights_cache.h), shared with the setups before and
                                  * after it; NULL: the setup builds its own */
} render_options;

#define RENDER_BAND_ROWS 16u /* rows of one band of a part: one row of tiles */

typedef struct render_stats {
    double build_seconds;   /* the setup: BVH, lights, crown proxies */
    double bvh_seconds;     /* of which the BVH (accel_build) */
    double render_seconds;  /* pixels */
    uint64_t samples;       /* camera samples traced (of this part alone) */
} render_stats;

/* Renders s; returns a new film (film_free) or NULL with err set. stats may be NULL. */
film *render_scene(const scene *s, const render_options *opt, render_stats *stats, err_buf *err);

/* The acceleration structure and the lights of one scene, built once for several renders of
 * it (the whole scene and the scene without its development, for compositing). */
typedef struct render_setup render_setup;

/* Builds s's setup with opt's threads, after checking that a frame of opt's size can be
 * rendered; NULL with err set. s must outlive it. The caller frees it (render_setup_free). */
render_setup *render_setup_new(const scene *s, const render_options *opt, err_buf *err);
/* Renders the setup's scene with opt (its size, samples, seed, mode and leave_out; its threads
 * and recorder as render_scene takes them); a new film (film_free) or NULL with err set. Renders
 * of one setup run one after another, never at once. stats may be NULL; its build_seconds is
 * the setup's. */
film *render_setup_run(render_setup *rs, const render_options *opt, render_stats *stats, err_buf *err);
void render_setup_free(render_setup *rs); /* accepts NULL */

unsigned render_default_threads(void);

#endif
