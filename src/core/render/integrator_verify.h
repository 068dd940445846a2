/* integrator_verify.h — the verification render's pixel (integrator.h describes its shading and
 * samples). */
#ifndef SYLVA_INTEGRATOR_VERIFY_H
#define SYLVA_INTEGRATOR_VERIFY_H

#include "render/integrator_ctx.h"

/* Pixel (x, y) as POV-Ray renders it: sets out's rgb, samples, coverage, development and
 * development_rgb. */
void integrator_verify_pixel(const render_ctx *ctx, uint32_t x, uint32_t y, pixel_result *out);

#endif
