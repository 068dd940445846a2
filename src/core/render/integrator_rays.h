/* integrator_rays.h — the rays every part of the integrator casts (integrator_path.c,
 * integrator_verify.c, integrator_aux.c): a ray's setup, a traced ray (shown to the recorder),
 * the camera ray straight or along the Earth's curve, a shadow ray's transmittance through the
 * crown proxies, the offset of a ray's origin off a surface, and whether a hit lies on the
 * development. Inline: they run for every ray. Internal to the integrator. */
#ifndef SYLVA_INTEGRATOR_RAYS_H
#define SYLVA_INTEGRATOR_RAYS_H

#include <math.h>

#include "render/accel.h"
#include "render/crown_proxy.h"
#include "render/integrator_ctx.h"

static inline void ray_init(struct RTCRayHit *rh, vec3 o, vec3 d, float tnear, float tfar, unsigned mask)
{
    rh->ray.org_x = o.x, rh->ray.org_y = o.y, rh->ray.org_z = o.z;
    rh->ray.dir_x = d.x, rh->ray.dir_y = d.y, rh->ray.dir_z = d.z;
    rh->ray.tnear = tnear, rh->ray.tfar = tfar;
    rh->ray.time = 0.0f, rh->ray.mask = mask, rh->ray.id = 0, rh->ray.flags = 0;
    rh->hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh->hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
}

static inline int trace(const render_ctx *ctx, struct RTCRayHit *rh)
{
    const accel *a = ctx->accel;
    if (ctx->recorder)
        ctx->recorder->record(ctx->recorder->user, v3(rh->ray.org_x, rh->ray.org_y, rh->ray.org_z),
                              v3(rh->ray.dir_x, rh->ray.dir_y, rh->ray.dir_z), rh->ray.tfar, 0);
    struct RTCIntersectContext ic;
    rtcInitIntersectContext(&ic);
    rtcIntersect1(a->top, &ic, rh);
    return rh->hit.geomID != RTC_INVALID_GEOMETRY_ID;
}

/* Traces the camera ray from o (the eye, or a point on the lens beside it) along unit d:
 * straight, or chord by chord along the Earth's curved path (curved_ray.h) moved by o's offset
 * from the eye. On a hit, rh holds the ray that met the surface (the chord, so that shading
 * works from the ray that really hit) and *t, when asked for, the hit's path parameter: its
 * distance along d, which the depth layer reads. On a miss rh holds the straight ray along d. */
static inline int trace_camera(const render_ctx *ctx, vec3 o, vec3 d, struct RTCRayHit *rh, float *t)
{
    vec3 shift = v3_sub(o, ctx->camera.origin);
    curved_path p;
    curved_path_begin(&p, &ctx->curved, d);
    vec3 org, dir;
    float len;
    double t0, dt;
    while (curved_path_next(&p, &org, &dir, &len, &t0, &dt)) {
        /* Chords overlap by a hundred-thousandth so that no hit falls between two of them. */
        ray_init(rh, v3_add(org, shift), dir, 0.0f, isinf(len) ? INFINITY : len * (1.0f + 1e-5f), ctx->camera_mask);
        if (!trace(ctx, rh)) continue;
        if (t) *t = isinf(len) ? rh->ray.tfar : (float)(t0 + rh->ray.tfar / len * dt);
        return 1;
    }
    ray_init(rh, o, d, 0.0f, INFINITY, ctx->camera_mask);
    return 0;
}

/* The share of light that passes from o + far d to o: 1 when nothing that mask meets is in the
 * way, 0 when something opaque is, between for crown proxies (crown_proxy.h). */
static inline float visible(const render_ctx *ctx, vec3 o, vec3 d, float far, unsigned mask)
{
    const accel *a = ctx->accel;
    if (ctx->recorder) ctx->recorder->record(ctx->recorder->user, o, d, far, 1);
    shadow_context sc = {.transmittance = 1.0f};
    rtcInitIntersectContext(&sc.ic);
    struct RTCRay r = {.org_x = o.x, .org_y = o.y, .org_z = o.z, .tnear = 0.0f, .dir_x = d.x, .dir_y = d.y,
                       .dir_z = d.z, .time = 0.0f, .tfar = far, .mask = mask, .id = 0, .flags = 0};
    rtcOccluded1(a->top, &sc.ic, &r);
    return r.tfar >= 0.0f ? sc.transmittance : 0.0f;
}

/* A point just off the surface on the side of direction d. p comes from the triangle's
 * barycentrics (accel_shade), so its error is a few float steps of its largest coordinate;
 * 1e-6 relative is about eight steps. With 0 the surface shadows itself everywhere; the
 * offset moves shadows by its size, which for centimetre leaves must stay well under 1 mm. */
static inline vec3 offset_point(vec3 p, vec3 ng, vec3 d)
{
    float scale = fmaxf(fabsf(p.x), fmaxf(fabsf(p.y), fabsf(p.z)));
    float eps = 1e-6f * (1.0f + scale);
    return v3_madd(p, ng, v3_dot(ng, d) >= 0.0f ? eps : -eps);
}

/* 1 when the camera ray's hit rh lies on an object of the development. */
static inline int on_development(const accel *a, const struct RTCRayHit *rh)
{
    uint32_t o = accel_hit_object(a, rh);
    if (o) return a->scene->objects[o - 1].development != 0;
    unsigned inst = rh->hit.instID[0];
    return inst != RTC_INVALID_GEOMETRY_ID && inst >= a->first_instance &&
           inst - a->first_instance < a->scene->n_instances && a->scene->instances[inst - a->first_instance].development;
}

#endif
