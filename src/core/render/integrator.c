/* integrator.c — path tracing with NEE and MIS, the verification shading, and the auxiliary
 * layers. */
#include "render/integrator.h"

#include <math.h>

#include "render/bsdf.h"
#include "render/sampler.h"

/* Sampler dimensions: 0-1 pixel position; then DIMS_PER_VERTEX per path vertex. */
enum { DIM_SUN = 0, DIM_SKY = 2, DIM_BSDF = 4, DIM_RR = 7, DIMS_PER_VERTEX = 8 };

static inline float power_heuristic(float a, float b)
{
    float a2 = a * a, b2 = b * b;
    return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

static void ray_init(struct RTCRayHit *rh, vec3 o, vec3 d, float tnear, float tfar)
{
    rh->ray.org_x = o.x, rh->ray.org_y = o.y, rh->ray.org_z = o.z;
    rh->ray.dir_x = d.x, rh->ray.dir_y = d.y, rh->ray.dir_z = d.z;
    rh->ray.tnear = tnear, rh->ray.tfar = tfar;
    rh->ray.time = 0.0f, rh->ray.mask = 0xffffffffu, rh->ray.id = 0, rh->ray.flags = 0;
    rh->hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh->hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
}

static int trace(const render_ctx *ctx, struct RTCRayHit *rh)
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

/* 1 when nothing blocks o + t d for t in (0, far). */
static int visible(const render_ctx *ctx, vec3 o, vec3 d, float far)
{
    const accel *a = ctx->accel;
    if (ctx->recorder) ctx->recorder->record(ctx->recorder->user, o, d, far, 1);
    struct RTCIntersectContext ic;
    rtcInitIntersectContext(&ic);
    struct RTCRay r = {.org_x = o.x, .org_y = o.y, .org_z = o.z, .tnear = 0.0f, .dir_x = d.x, .dir_y = d.y,
                       .dir_z = d.z, .time = 0.0f, .tfar = far, .mask = 0xffffffffu, .id = 0, .flags = 0};
    rtcOccluded1(a->top, &ic, &r);
    return r.tfar >= 0.0f;
}

/* A point just off the surface on the side of direction d. */
static vec3 offset_point(vec3 p, vec3 ng, vec3 d)
{
    float scale = fmaxf(fabsf(p.x), fmaxf(fabsf(p.y), fabsf(p.z)));
    float eps = 1e-4f * (1.0f + scale);
    return v3_madd(p, ng, v3_dot(ng, d) >= 0.0f ? eps : -eps);
}

static vec3 path_radiance(const render_ctx *ctx, const sampler *smp, vec3 o, vec3 d)
{
    const accel *a = ctx->accel;
    const lights *l = ctx->lights;
    vec3 L = v3(0, 0, 0), beta = v3(1, 1, 1);
    float prev_pdf = 0.0f; /* 0: the previous vertex was the camera (no MIS on emission) */
    for (uint32_t depth = 0;; depth++) {
        struct RTCRayHit rh;
        ray_init(&rh, o, d, 0.0f, INFINITY);
        if (!trace(ctx, &rh)) {
            /* The camera sees the exact sky; light reaching surfaces uses the tabulated sky, the
             * same function next-event estimation samples, so both MIS strategies agree. */
            if (prev_pdf > 0.0f && l->table.rgb) {
                float rgb[3], fd[3] = {d.x, d.y, d.z};
                float w = power_heuristic(prev_pdf, sky_table_pdf(&l->table, fd, rgb));
                L = v3_add(L, v3_scale(v3_mul(beta, v3(rgb[0], rgb[1], rgb[2])), w));
            } else {
                L = v3_add(L, v3_mul(beta, lights_sky(l, d)));
            }
            if (lights_in_sun(l, d)) {
                float ws = prev_pdf > 0.0f ? power_heuristic(prev_pdf, 1.0f / l->solid_angle) : 1.0f;
                L = v3_add(L, v3_scale(v3_mul(beta, l->sun_radiance), ws));
            }
            break;
        }
        if (depth >= ctx->max_depth) break;
        hit_info h;
        accel_shade(a, &rh, &h);
        vec3 wo = v3_scale(d, -1.0f);
        vec3 ng = v3_dot(h.ng, wo) < 0.0f ? v3_scale(h.ng, -1.0f) : h.ng;
        vec3 n = v3_dot(h.ns, ng) < 0.0f ? v3_scale(h.ns, -1.0f) : h.ns;
        uint32_t base = 2 + depth * DIMS_PER_VERTEX;

        /* next-event estimation: the sun */
        if (l->sun_on) {
            vec3 wi;
            float pdf_l = lights_sun_sample(l, sampler_at(smp, base + DIM_SUN), sampler_at(smp, base + DIM_SUN + 1), &wi);
            float pdf_b;
            vec3 f = bsdf_eval(h.mat, h.albedo, n, wo, wi, &pdf_b);
            float c = fabsf(v3_dot(n, wi));
            if (v3_max(f) > 0.0f && c > 0.0f && visible(ctx, offset_point(h.p, ng, wi), wi, INFINITY)) {
                vec3 contrib;
                if (l->solid_angle > 0.0f)
                    contrib = v3_scale(v3_mul(f, l->sun_radiance), c / pdf_l * power_heuristic(pdf_l, pdf_b));
                else
                    contrib = v3_scale(v3_mul(f, l->sun_irradiance), c);
                L = v3_add(L, v3_mul(beta, contrib));
            }
        }
        /* next-event estimation: the sky */
        if (l->table.rgb) {
            float fwi[3], rgb[3];
            float pdf_l = sky_table_sample(&l->table, sampler_at(smp, base + DIM_SKY),
                                           sampler_at(smp, base + DIM_SKY + 1), fwi, rgb);
            vec3 wi = v3(fwi[0], fwi[1], fwi[2]);
            float pdf_b;
            vec3 f = bsdf_eval(h.mat, h.albedo, n, wo, wi, &pdf_b);
            float c = fabsf(v3_dot(n, wi));
            if (pdf_l > 0.0f && v3_max(f) > 0.0f && c > 0.0f && visible(ctx, offset_point(h.p, ng, wi), wi, INFINITY)) {
                vec3 Ls = v3(rgb[0], rgb[1], rgb[2]);
                L = v3_add(L, v3_mul(beta, v3_scale(v3_mul(f, Ls), c / pdf_l * power_heuristic(pdf_l, pdf_b))));
            }
        }
        /* continue the path */
        bsdf_sample bs;
        if (!bsdf_sample_dir(h.mat, h.albedo, n, wo, sampler_at(smp, base + DIM_BSDF), sampler_at(smp, base + DIM_BSDF + 1),
                             sampler_at(smp, base + DIM_BSDF + 2), &bs))
            break;
        beta = v3_mul(beta, v3_scale(bs.f, fabsf(v3_dot(n, bs.wi)) / bs.pdf));
        if (depth >= 3) {
            float q = fminf(0.95f, v3_max(beta));
            if (sampler_at(smp, base + DIM_RR) >= q) break;
            beta = v3_scale(beta, 1.0f / q);
        }
        if (!(v3_max(beta) > 0.0f)) break;
        o = offset_point(h.p, ng, bs.wi);
        d = bs.wi;
        prev_pdf = bs.pdf;
    }
    return L;
}

static vec3 verify_radiance(const render_ctx *ctx, vec3 o, vec3 d)
{
    const accel *a = ctx->accel;
    const lights *l = ctx->lights;
    struct RTCRayHit rh;
    ray_init(&rh, o, d, 0.0f, INFINITY);
    if (!trace(ctx, &rh)) return l->sky_mean;
    hit_info h;
    accel_shade(a, &rh, &h);
    vec3 wo = v3_scale(d, -1.0f);
    vec3 n = v3_dot(h.ns, wo) < 0.0f ? v3_scale(h.ns, -1.0f) : h.ns;
    vec3 ng = v3_dot(h.ng, wo) < 0.0f ? v3_scale(h.ng, -1.0f) : h.ng;
    vec3 E = l->ambient;
    float c = v3_dot(n, l->sun_dir);
    if (l->sun_on && c > 0.0f && visible(ctx, offset_point(h.p, ng, l->sun_dir), l->sun_dir, INFINITY))
        E = v3_add(E, v3_scale(l->sun_irradiance, c));
    return v3_mul(h.albedo, E);
}

static void aux_layers(const render_ctx *ctx, uint32_t x, uint32_t y, pixel_result *out)
{
    vec3 d = camera_direction(&ctx->camera, x + 0.5f, y + 0.5f);
    struct RTCRayHit rh;
    ray_init(&rh, ctx->camera.origin, d, 0.0f, INFINITY);
    if (!trace(ctx, &rh)) {
        out->depth = INFINITY;
        out->normal = v3(0, 0, 0), out->albedo = v3(0, 0, 0);
        out->instance_id = out->species_id = 0;
        return;
    }
    hit_info h;
    accel_shade(ctx->accel, &rh, &h);
    out->depth = h.t * v3_dot(d, ctx->camera.forward);
    out->normal = v3_dot(h.ns, d) > 0.0f ? v3_scale(h.ns, -1.0f) : h.ns;
    out->albedo = h.albedo;
    out->instance_id = h.instance_id;
    out->species_id = h.species_id;
}

void integrate_pixel(const render_ctx *ctx, uint32_t x, uint32_t y, pixel_result *out)
{
    uint64_t pixel = (uint64_t)y * ctx->camera.width + x;
    vec3 sum = v3(0, 0, 0);
    uint32_t grid = 1;
    while ((grid + 1) * (grid + 1) <= ctx->spp) grid++;
    uint32_t n = ctx->verify ? grid * grid : ctx->spp; /* verification: spp rounded down to a square */
    for (uint32_t s = 0; s < n; s++) {
        sampler smp;
        sampler_start(&smp, ctx->seed, pixel, s);
        float sx, sy;
        if (ctx->verify) {
            sx = ((s % grid) + 0.5f) / grid;
            sy = ((s / grid) + 0.5f) / grid;
        } else {
            sx = sampler_at(&smp, 0), sy = sampler_at(&smp, 1);
        }
        vec3 d = camera_direction(&ctx->camera, x + sx, y + sy);
        vec3 L = ctx->verify ? verify_radiance(ctx, ctx->camera.origin, d) : path_radiance(ctx, &smp, ctx->camera.origin, d);
        if (!(isfinite(L.x) && isfinite(L.y) && isfinite(L.z))) L = v3(0, 0, 0);
        sum = v3_add(sum, L);
    }
    out->rgb = v3_scale(sum, 1.0f / (float)n);
    aux_layers(ctx, x, y, out);
}
