/* integrator_aux.h — the auxiliary layers of a pixel (integrator.h). */
#ifndef SYLVA_INTEGRATOR_AUX_H
#define SYLVA_INTEGRATOR_AUX_H

#include "render/integrator_ctx.h"

/* Sets out's depth, normal, albedo, instance_id, species_id, object_id and pixel_class from one
 * camera ray through the centre of pixel (x, y). */
void integrator_aux_layers(const render_ctx *ctx, uint32_t x, uint32_t y, pixel_result *out);

#endif
