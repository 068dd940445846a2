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
 * sees the sky in the direction it left the camera.
 *
 * Files: integrator_path.c the path tracer, integrator_verify.c the verification mode,
 * integrator_aux.c the auxiliary layers, integrator_rays.h the rays all three cast;
 * integrator.c chooses by the mode. */
#ifndef SYLVA_INTEGRATOR_H
#define SYLVA_INTEGRATOR_H

#include "render/integrator_ctx.h"  /* render_ctx, pixel_result */
#include "render/integrator_path.h" /* integrate_sample */

void integrate_pixel(const render_ctx *ctx, uint32_t x, uint32_t y, pixel_result *out);

#endif
