/* integrator_aux.c — the auxiliary layers of a pixel: depth, normal, albedo, ids and class from
 * one camera ray through its centre (integrator.h). */
#include "render/integrator_aux.h"

#include <math.h>

#include "render/film.h"
#include "render/integrator_rays.h"

void integrator_aux_layers(const render_ctx *ctx, uint32_t x, uint32_t y, pixel_result *out)
{
    vec3 d = camera_direction(&ctx->camera, x + 0.5f, y + 0.5f);
    struct RTCRayHit rh;
    float t;
    if (!trace_camera(ctx, ctx->camera.origin, d, &rh, &t)) {
        out->depth = INFINITY;
        out->normal = v3(0, 0, 0), out->albedo = v3(0, 0, 0);
        out->instance_id = out->species_id = out->object_id = 0;
        out->pixel_class = PIXEL_SKY;
        return;
    }
    hit_info h;
    accel_shade(ctx->accel, &rh, &h);
    /* depth: along the view axis; for a panorama, from the cylinder's axis (the camera's up) */
    float up = v3_dot(d, ctx->camera.up);
    out->depth = ctx->camera.cylindrical ? t * sqrtf(fmaxf(0.0f, 1.0f - up * up)) : t * v3_dot(d, ctx->camera.forward);
    out->normal = v3_dot(h.ns, d) > 0.0f ? v3_scale(h.ns, -1.0f) : h.ns;
    out->albedo = h.albedo;
    out->instance_id = h.instance_id;
    out->species_id = h.species_id;
    out->object_id = h.object_id;
    switch (h.kind) {
    case GEOM_TERRAIN:
    case GEOM_WATER: out->pixel_class = PIXEL_TERRAIN; break;
    case GEOM_PROTOTYPE: out->pixel_class = h.mat->bsdf == SYLVA_BSDF_LEAF ? PIXEL_LEAVES : PIXEL_BARK; break;
    case GEOM_OBJECT: out->pixel_class = PIXEL_OBJECT; break;
    }
}
