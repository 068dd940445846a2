/* integrator_ctx.h — what the integrator is given (render_ctx: the scene in Embree, the lights,
 * the camera, the samples, the mode and the ray masks) and what it gives for a pixel
 * (pixel_result). integrator.h describes how each is used. */
#ifndef SYLVA_INTEGRATOR_CTX_H
#define SYLVA_INTEGRATOR_CTX_H

#include <stdint.h>

#include "render/accel.h"
#include "render/camera.h"
#include "render/curved_ray.h"
#include "render/lights.h"

/* Receives every ray the integrator casts (benchmarks replay them on bare Embree). */
typedef struct ray_recorder {
    void (*record)(void *user, vec3 org, vec3 dir, float tfar, int shadow);
    void *user;
} ray_recorder;

typedef struct render_ctx {
    const accel *accel;
    const lights *lights;
    camera camera;
    curved_rays curved;  /* camera rays over the curved Earth, or straight (curved.on 0) */
    uint32_t spp, max_depth;
    float noise_target;   /* adaptive sampling (integrate_pixel); 0: every pixel takes spp */
    uint64_t seed;
    int verify;
    unsigned ray_mask;  /* the geometry rays meet (ACCEL_MASK_* bits); ~0u: all */
    unsigned camera_mask; /* the geometry camera rays meet */
    const ray_recorder *recorder; /* NULL, or called for each ray (single-threaded renders only) */
} render_ctx;

typedef struct pixel_result {
    vec3 rgb;
    float depth;
    vec3 normal;
    vec3 albedo;
    uint32_t instance_id, species_id, object_id;
    uint8_t pixel_class;  /* a pixel_class (render/film.h) */
    uint32_t samples;     /* camera samples taken */
    float coverage;
    float development;
    vec3 development_rgb;
} pixel_result;

#endif
