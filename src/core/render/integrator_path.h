/* integrator_path.h — the path tracer's pixel and camera sample (integrator.h describes the
 * paths). */
#ifndef SYLVA_INTEGRATOR_PATH_H
#define SYLVA_INTEGRATOR_PATH_H

#include "render/integrator_ctx.h"

/* Pixel (x, y) by path tracing: sets out's rgb (the samples' mean), samples, coverage,
 * development and development_rgb; adaptive when ctx->noise_target > 0. */
void integrator_path_pixel(const render_ctx *ctx, uint32_t x, uint32_t y, pixel_result *out);

/* The radiance of camera sample s of pixel (x, y), as integrate_pixel sums it; *proxy (when not
 * NULL) the crown proxy its camera ray met first (index + 1), or 0. */
vec3 integrate_sample(const render_ctx *ctx, uint32_t x, uint32_t y, uint32_t s, uint32_t *proxy);

#endif
