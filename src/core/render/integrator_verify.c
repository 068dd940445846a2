/* integrator_verify.c — the verification render: a pixel shaded as POV-Ray shades the scene's
 * export, from the samples POV-Ray's non-adaptive antialiasing takes (integrator.h). */
#include "render/integrator_verify.h"

#include <math.h>

#include "render/integrator_rays.h"

#define VERIFY_STREAM 64 /* camera rays of one pixel traced together as a coherent stream */

/* The verification samples of pixel (x, y): the centre, then (grid > 1) a grid x grid grid;
 * camera rays go to Embree as coherent streams, then the shadow rays of the hits the sun can
 * light. Sets out's samples to their count, rgb to their mean, coverage to the share that hit a
 * surface, development to the share that hit the development and development_rgb to those
 * samples' radiance over all samples. */
static void verify_pixel(const render_ctx *ctx, uint32_t x, uint32_t y, uint32_t grid, pixel_result *out)
{
    const accel *a = ctx->accel;
    const light_summary *l = &ctx->lights->summary;
    const uint32_t n = grid > 1 ? grid * grid + 1 : 1;
    struct RTCRayHit rh[VERIFY_STREAM];
    struct RTCRay shadow[VERIFY_STREAM];
    vec3 albedo[VERIFY_STREAM];
    float cosine[VERIFY_STREAM]; /* n.l where the sun may light the hit, else 0 */
    float dist[VERIFY_STREAM];   /* from the camera to the hit, for the fog; INFINITY for none */
    uint32_t owner[VERIFY_STREAM], hits = 0, dev_hits = 0;
    struct RTCIntersectContext ic;
    uint8_t on_dev[VERIFY_STREAM];
    vec3 sum = v3(0, 0, 0), dev_sum = v3(0, 0, 0);
    for (uint32_t s0 = 0; s0 < n; s0 += VERIFY_STREAM) {
        uint32_t m = n - s0 < VERIFY_STREAM ? n - s0 : VERIFY_STREAM, k = 0;
        for (uint32_t i = 0; i < m; i++) {
            uint32_t s = s0 + i, g = s ? s - 1 : 0;
            float sx = s ? ((g % grid) + 0.5f) / grid : 0.5f, sy = s ? ((g / grid) + 0.5f) / grid : 0.5f;
            vec3 d = camera_direction(&ctx->camera, x + sx, y + sy);
            if (ctx->curved.on) {
                trace_camera(ctx, ctx->camera.origin, d, &rh[i], NULL); /* chord by chord, one ray at a time */
                continue;
            }
            ray_init(&rh[i], ctx->camera.origin, d, 0.0f, INFINITY, ctx->ray_mask);
            if (ctx->recorder) ctx->recorder->record(ctx->recorder->user, ctx->camera.origin, d, INFINITY, 0);
        }
        if (!ctx->curved.on) {
            rtcInitIntersectContext(&ic);
            ic.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
            rtcIntersect1M(a->top, &ic, rh, m, sizeof rh[0]);
        }
        for (uint32_t i = 0; i < m; i++) {
            cosine[i] = 0.0f;
            on_dev[i] = 0;
            dist[i] = INFINITY;
            if (rh[i].hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
            hits++;
            on_dev[i] = (uint8_t)on_development(a, &rh[i]);
            dev_hits += on_dev[i];
            hit_info h;
            accel_shade(a, &rh[i], &h);
            dist[i] = v3_len(v3_sub(h.p, ctx->camera.origin));
            vec3 wo = v3(-rh[i].ray.dir_x, -rh[i].ray.dir_y, -rh[i].ray.dir_z);
            /* a triangle whose three normals are one vector POV-Ray shades by its geometric
             * normal (a strip of the terrain's apron: normals straight up, sloping along the
             * edge) */
            vec3 ns = h.one_normal ? h.ng : h.ns;
            vec3 nrm = v3_dot(ns, wo) < 0.0f ? v3_scale(ns, -1.0f) : ns;
            vec3 ng = v3_dot(h.ng, wo) < 0.0f ? v3_scale(h.ng, -1.0f) : h.ng;
            albedo[i] = h.albedo;
            float c = v3_dot(nrm, l->sun_dir);
            if (!l->sun_on || !(c > 0.0f)) continue;
            vec3 o = offset_point(h.p, ng, l->sun_dir);
            shadow[k] = (struct RTCRay){.org_x = o.x, .org_y = o.y, .org_z = o.z, .tnear = 0.0f, .dir_x = l->sun_dir.x,
                                        .dir_y = l->sun_dir.y, .dir_z = l->sun_dir.z, .time = 0.0f, .tfar = INFINITY,
                                        .mask = ctx->ray_mask, .id = 0, .flags = 0};
            if (ctx->recorder) ctx->recorder->record(ctx->recorder->user, o, l->sun_dir, INFINITY, 1);
            cosine[i] = c;
            owner[k++] = i;
        }
        if (k) {
            rtcInitIntersectContext(&ic);
            ic.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
            rtcOccluded1M(a->top, &ic, shadow, k, sizeof shadow[0]);
            for (uint32_t j = 0; j < k; j++)
                if (shadow[j].tfar < 0.0f) cosine[owner[j]] = 0.0f;
        }
        for (uint32_t i = 0; i < m; i++) {
            vec3 L = l->sky_mean;
            if (rh[i].hit.geomID != RTC_INVALID_GEOMETRY_ID)
                L = v3_mul(albedo[i], cosine[i] > 0.0f ? v3_add(l->ambient, v3_scale(l->sun_irradiance, cosine[i]))
                                                       : l->ambient);
            L = light_summary_fog(l, L, dist[i]); /* POV-Ray's constant fog, misses included */
            if (!(isfinite(L.x) && isfinite(L.y) && isfinite(L.z))) continue;
            sum = v3_add(sum, L);
            if (on_dev[i]) dev_sum = v3_add(dev_sum, L);
        }
    }
    out->samples = n;
    out->rgb = v3_scale(sum, 1.0f / (float)n);
    out->coverage = (float)hits / (float)n;
    out->development = (float)dev_hits / (float)n;
    out->development_rgb = v3_scale(dev_sum, 1.0f / (float)n);
}

void integrator_verify_pixel(const render_ctx *ctx, uint32_t x, uint32_t y, pixel_result *out)
{
    uint32_t grid = 1; /* spp rounded down to a square */
    while ((grid + 1) * (grid + 1) <= ctx->spp) grid++;
    verify_pixel(ctx, x, y, grid, out);
}
