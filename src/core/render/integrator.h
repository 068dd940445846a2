/* integrator.h — what one pixel sees.
 *
 * Path tracing: unidirectional paths from the camera (through the thin lens and weighted by the
 * vignette when the camera has them, render/lens.h; the verification mode and the auxiliary
 * layers use the pinhole); at each vertex next-event estimation of
 * the sun and of the sky's part above its base (both at the first vertex, one chosen by their
 * expected contributions at later ones), each combined with BSDF sampling by multiple
 * importance sampling (power heuristic), the sky's base reached by BSDF sampling alone;
 * Russian roulette from the fourth vertex on; at most max_depth vertices. Sample values come
 * from render/sampler.h (Owen-scrambled Sobol, keyed by seed, pixel, sample and dimension).
 *
 * Verification mode: what POV-Ray computes from the same scene — at the first hit,
 * albedo * (ambient + sun irradiance * max(0, n.l) * visibility), with the normal turned toward
 * the viewer, hard shadows from a point-like sun, no indirect light; rays that miss show the
 * sky's mean colour. Samples as POV-Ray's non-adaptive antialiasing (method 1, threshold 0, no
 * jitter) takes them: below 4 spp one ray through the pixel centre; otherwise spp is rounded
 * down to a square R x R and the pixel is the equally weighted mean of the centre ray and a
 * regular R x R grid of rays at sub-pixel offsets (i + 0.5) / R - 0.5.
 *
 * Auxiliary layers (depth, normal, albedo, ids, class) come from one ray through the pixel
 * centre; coverage is the share of the camera samples whose first ray hit a surface,
 * development the share whose first ray hit an object marked as part of the development, and
 * development_rgb those samples' radiance summed and divided by all samples (the part of rgb the
 * development's own surfaces send to the camera).
 *
 * With the physical sky every segment that meets a surface (camera ray and bounces, not shadow
 * rays) takes the air's extinction and in-scattered light (aerial.h); the verification mode
 * applies it as POV-Ray's constant fog (light_summary_fog), misses included.
 *
 * Every ray after the camera ray (bounce, shadow) carries ctx->ray_mask, camera rays carry
 * ctx->camera_mask: geometry whose Embree mask (ACCEL_MASK_*) shares no bit with it is not in
 * the scene for those rays (crown proxies meet camera rays alone: render/crown_proxy.h).
 *
 * Camera rays follow the Earth's curvature when ctx->curved is on (curved_ray.h), in both modes;
 * the rays after the first hit (shadows, bounces) are straight, and a camera ray that misses
 * sees the sky in the direction it left the camera. */
#ifndef SYLVA_INTEGRATOR_H
#define SYLVA_INTEGRATOR_H

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

void integrate_pixel(const render_ctx *ctx, uint32_t x, uint32_t y, pixel_result *out);
/* The radiance of camera sample s of pixel (x, y), as integrate_pixel sums it; *proxy (when not
 * NULL) the crown proxy its camera ray met first (index + 1), or 0. */
vec3 integrate_sample(const render_ctx *ctx, uint32_t x, uint32_t y, uint32_t s, uint32_t *proxy);

#endif
