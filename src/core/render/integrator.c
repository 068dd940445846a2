/* integrator.c — a pixel by the render's mode: path traced (integrator_path.c) or as the
 * verification render (integrator_verify.c), then its auxiliary layers (integrator_aux.c). */
#include "render/integrator.h"

#include "render/integrator_aux.h"
#include "render/integrator_path.h"
#include "render/integrator_verify.h"

void integrate_pixel(const render_ctx *ctx, uint32_t x, uint32_t y, pixel_result *out)
{
    if (ctx->verify)
        integrator_verify_pixel(ctx, x, y, out);
    else
        integrator_path_pixel(ctx, x, y, out);
    integrator_aux_layers(ctx, x, y, out);
}
