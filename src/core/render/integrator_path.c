/* integrator_path.c — the path tracer: a camera sample's radiance by unidirectional paths with
 * next-event estimation of the sun and the sky, multiple importance sampling and Russian
 * roulette, and a pixel's mean over its samples, adaptive when asked (integrator.h). */
#include "render/integrator_path.h"

#include <math.h>

#include "render/aerial.h"
#include "render/bsdf.h"
#include "render/integrator_rays.h"
#include "render/lens.h"
#include "render/sampler.h"

/* Sampler dimensions (sampler.h), 2-D points in consecutive pairs: the position in the pixel,
 * the point on the lens, then DIMS_PER_VERTEX for each path vertex from DIM_VERTEX on: the light
 * sample (the sun's, or the one light's), the sky's when both are sampled, the BSDF direction
 * (pairs), the BSDF's lobe and Russian roulette. */
enum { DIM_PIXEL = 0, DIM_LENS = 2, DIM_VERTEX = 4 };
enum { DIM_LIGHT = 0, DIM_LIGHT2 = 2, DIM_BSDF = 4, DIM_LOBE = 6, DIM_RR = 7, DIMS_PER_VERTEX = 8 };

static inline float power_heuristic(float a, float b)
{
    float a2 = a * a, b2 = b * b;
    return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

/* 1 when the sky's table holds radiance above its base (next-event estimation's part). */
static int sky_varies(const lights *l) { return l->table.rgb && l->table.cdf_rows[l->table.nt] > 0.0f; }

/* The probabilities p[0] of the sun's and p[1] of the sky's next-event estimation at hit h
 * (shading normal n toward wo). At the first vertex each light that can contribute is sampled
 * (probability 1): there the sun's sample is nearly free of noise and the sky's carries it, so
 * thinning either costs more than the shadow ray it saves. At deeper vertices one light is
 * sampled, chosen by the lights' expected contributions without shadows: the sun's
 * f(wo, sun) |n.sun| E, the sky's the surface's reflectance (and a leaf's transmittance) over pi
 * times the irradiance of the sky above its base on the normal's side (and the other side),
 * interpolated between the table's irradiance on surfaces facing up and down. Any
 * probabilities keep the estimate unbiased: the MIS weights use them, and a light left out (an
 * expected contribution of 0) is still met by BSDF sampling. */
static void light_probabilities(const lights *l, const hit_info *h, vec3 n, vec3 wo, int first, float p[2])
{
    float e[2] = {0.0f, 0.0f};
    if (l->summary.sun_on) {
        vec3 s = l->summary.sun_dir;
        float pdf;
        e[0] = v3_luminance(bsdf_eval(h->mat, h->albedo, n, wo, s, &pdf)) * fabsf(v3_dot(n, s)) *
               v3_luminance(l->summary.sun_irradiance);
        /* a point-like sun is met by nothing else: sample it whenever it can light h (as at the
         * first vertex, so the sky is sampled too: a shadow ray more per vertex, no bias) */
        if (l->summary.solid_angle <= 0.0f && e[0] > 0.0f) first = 1;
    }
    if (sky_varies(l)) {
        float up = 0.5f + 0.5f * n.z, front = up * l->table.irradiance_up + (1.0f - up) * l->table.irradiance_down,
              back = up * l->table.irradiance_down + (1.0f - up) * l->table.irradiance_up;
        e[1] = v3_luminance(h->albedo) * front;
        if (h->mat->bsdf == SYLVA_BSDF_LEAF) e[1] += v3_luminance(h->mat->transmittance) * back;
        e[1] *= (float)M_1_PI;
    }
    float total = e[0] + e[1];
    for (int j = 0; j < 2; j++) p[j] = !(e[j] > 0.0f) ? 0.0f : first ? 1.0f : e[j] / total;
}

/* *hit: 0 when the camera ray hit nothing, 1 when it hit a surface, 2 when that surface is part
 * of the development. *proxy (when not NULL): the crown proxy the camera ray met (its index + 1),
 * or 0. */
static vec3 path_radiance(const render_ctx *ctx, const sampler *smp, vec3 o, vec3 d, int *hit,
                          uint32_t *proxy)
{
    const accel *a = ctx->accel;
    const lights *l = ctx->lights;
    vec3 L = v3(0, 0, 0), beta = v3(1, 1, 1);
    float prev_pdf = 0.0f; /* 0: the previous vertex was the camera (no MIS on emission) */
    float prev_p[2] = {0.0f, 0.0f}; /* the previous vertex's light probabilities (sun, sky) */
    unsigned mask = ctx->ray_mask; /* a path from a crown proxy stays among the proxies */
    const unsigned shadow_mask = ctx->camera_mask; /* shadows cross the proxies, not the far plants */
    for (uint32_t depth = 0;; depth++) {
        struct RTCRayHit rh;
        int found;
        if (depth == 0) {
            found = trace_camera(ctx, o, d, &rh, NULL);
            *hit = found ? 1 + on_development(a, &rh) : 0;
            uint32_t j = found ? crown_proxy_of_hit(a, &rh) : 0;
            if (j) mask = ctx->camera_mask;
            if (proxy) *proxy = j;
        } else {
            ray_init(&rh, o, d, 0.0f, INFINITY, mask);
            found = trace(ctx, &rh);
        }
        if (!found) {
            /* The camera sees the exact sky; light reaching surfaces uses the tabulated sky, the
             * same function next-event estimation samples, so both MIS strategies agree. The
             * table's base is BSDF sampling's alone (weight 1), the part above it is
             * shared with next-event estimation. */
            if (prev_pdf > 0.0f && l->table.rgb) {
                float above[3], below[3], fd[3] = {d.x, d.y, d.z};
                float w = power_heuristic(prev_pdf, prev_p[1] * sky_table_pdf(&l->table, fd, above, below));
                vec3 sky = v3_add(v3(below[0], below[1], below[2]), v3_scale(v3(above[0], above[1], above[2]), w));
                L = v3_add(L, v3_mul(beta, sky));
            } else {
                L = v3_add(L, v3_mul(beta, light_summary_sky(&l->summary, d)));
            }
            if (lights_in_sun(l, d)) {
                float ws = prev_pdf > 0.0f ? power_heuristic(prev_pdf, prev_p[0] / l->summary.solid_angle) : 1.0f;
                L = v3_add(L, v3_scale(v3_mul(beta, l->summary.sun_radiance), ws));
            }
            break;
        }
        if (depth >= ctx->max_depth) break;
        hit_info h;
        accel_shade(a, &rh, &h);
        aerial_segment(&l->summary, o, h.p, &L, &beta); /* the air between o and the hit */
        vec3 wo = v3_scale(d, -1.0f);
        vec3 ng = v3_dot(h.ng, wo) < 0.0f ? v3_scale(h.ng, -1.0f) : h.ng;
        vec3 n = v3_dot(h.ns, ng) < 0.0f ? v3_scale(h.ns, -1.0f) : h.ns;
        uint32_t base = DIM_VERTEX + depth * DIMS_PER_VERTEX;

        /* next-event estimation (light_probabilities): both lights, each from a pair of its own,
         * or one, chosen by where the first pair's u falls (the rest of u places the point on it) */
        float p_light[2];
        light_probabilities(l, &h, n, wo, depth == 0, p_light);
        int one = p_light[0] + p_light[1] <= 1.0f;
        for (int j = 0; j < 2; j++) {
            float u, v, pdf_l, pdf_b, p = p_light[j], lo = one && j ? p_light[0] : 0.0f;
            if (!(p > 0.0f)) continue;
            sampler_2d(smp, base + (j && !one ? DIM_LIGHT2 : DIM_LIGHT), &u, &v);
            if (u < lo || u >= lo + p) continue;
            u = fminf((u - lo) / p, 0x1.fffffep-1f);
            vec3 wi, Le;
            if (j == 0) {
                pdf_l = lights_sun_sample(l, u, v, &wi);
                Le = l->summary.solid_angle > 0.0f ? l->summary.sun_radiance : l->summary.sun_irradiance;
            } else {
                float fwi[3], rgb[3];
                pdf_l = sky_table_sample(&l->table, u, v, fwi, rgb);
                wi = v3(fwi[0], fwi[1], fwi[2]), Le = v3(rgb[0], rgb[1], rgb[2]);
            }
            vec3 f = bsdf_eval(h.mat, h.albedo, n, wo, wi, &pdf_b);
            float c = fabsf(v3_dot(n, wi)), vis;
            if (pdf_l > 0.0f && v3_max(f) > 0.0f && c > 0.0f &&
                (vis = visible(ctx, offset_point(h.p, ng, wi), wi, INFINITY, shadow_mask)) > 0.0f) {
                /* a point-like sun is a delta: its pdf 1 stands for the irradiance, no MIS */
                float w = j == 0 && l->summary.solid_angle <= 0.0f ? 1.0f : power_heuristic(p * pdf_l, pdf_b);
                L = v3_add(L, v3_mul(beta, v3_scale(v3_mul(f, Le), c * vis * w / (p * pdf_l))));
            }
        }
        /* continue the path */
        bsdf_sample bs;
        float u, v;
        sampler_2d(smp, base + DIM_BSDF, &u, &v);
        if (!bsdf_sample_dir(h.mat, h.albedo, n, wo, sampler_1d(smp, base + DIM_LOBE), u, v, &bs))
            break;
        beta = v3_mul(beta, v3_scale(bs.f, fabsf(v3_dot(n, bs.wi)) / bs.pdf));
        if (depth >= 3) {
            float q = fminf(0.95f, v3_max(beta));
            if (sampler_1d(smp, base + DIM_RR) >= q) break;
            beta = v3_scale(beta, 1.0f / q);
        }
        if (!(v3_max(beta) > 0.0f)) break;
        o = offset_point(h.p, ng, bs.wi);
        d = bs.wi;
        prev_pdf = bs.pdf;
        prev_p[0] = p_light[0], prev_p[1] = p_light[1];
    }
    return L;
}

/* Sample s of pixel (x, y): its radiance (0 when not finite); *hit and *proxy as path_radiance. */
static vec3 camera_sample(const render_ctx *ctx, uint32_t x, uint32_t y, uint32_t s, int *hit, uint32_t *proxy)
{
    sampler smp;
    sampler_start(&smp, ctx->seed, (uint64_t)y * ctx->camera.width + x, s);
    float px, py;
    sampler_2d(&smp, DIM_PIXEL, &px, &py);
    vec3 d = camera_direction(&ctx->camera, x + px, y + py), o = ctx->camera.origin;
    float vignette = lens_vignette(&ctx->camera, d);
    if (ctx->camera.lens_radius > 0.0f) {
        float lu, lv;
        sampler_2d(&smp, DIM_LENS, &lu, &lv);
        lens_ray(&ctx->camera, lu, lv, &o, &d);
    }
    vec3 L = v3_scale(path_radiance(ctx, &smp, o, d, hit, proxy), vignette);
    return isfinite(L.x) && isfinite(L.y) && isfinite(L.z) ? L : v3(0, 0, 0);
}

vec3 integrate_sample(const render_ctx *ctx, uint32_t x, uint32_t y, uint32_t s, uint32_t *proxy)
{
    int hit;
    return camera_sample(ctx, x, y, s, &hit, proxy);
}

/* Adaptive sampling: a pixel may stop at ADAPTIVE_FIRST samples or any power of two after it
 * (where the sampler's strata are complete), once the standard error of its mean luminance,
 * estimated from the samples' variance, is at most target times the mean. The variance of
 * stratified samples overstates the error of their mean, so the test errs toward more samples.
 * The variance is taken as at least mean^2 / n: n samples that happen to agree (a pixel whose
 * rarer paths, a bounce that meets an object, none has taken yet) have not shown that an event
 * of probability 1 / n is absent, so no pixel stops before 1 / target samples. It depends on the
 * pixel's own samples alone: deterministic for any thread count. */
#define ADAPTIVE_FIRST 16u

static int adaptive_done(double lum, double lum2, uint32_t n, float target)
{
    double mean = lum / n, var = fmax((lum2 - lum * mean) / (n - 1), mean * mean / n);
    return var / n <= (double)target * target * mean * mean;
}

void integrator_path_pixel(const render_ctx *ctx, uint32_t x, uint32_t y, pixel_result *out)
{
    vec3 sum = v3(0, 0, 0), dev_sum = v3(0, 0, 0);
    uint32_t n = 0, hits = 0, dev_hits = 0;
    double lum = 0.0, lum2 = 0.0; /* the samples' luminance and its square, summed */
    while (n < ctx->spp) {
        int hit = 0;
        vec3 L = camera_sample(ctx, x, y, n++, &hit, NULL);
        sum = v3_add(sum, L);
        hits += hit != 0;
        dev_hits += hit == 2;
        if (hit == 2) dev_sum = v3_add(dev_sum, L);
        double l = v3_luminance(L);
        lum += l, lum2 += l * l;
        if (ctx->noise_target > 0.0f && n >= ADAPTIVE_FIRST && (n & (n - 1)) == 0 &&
            adaptive_done(lum, lum2, n, ctx->noise_target))
            break;
    }
    out->rgb = v3_scale(sum, 1.0f / (float)n);
    out->samples = n;
    out->coverage = (float)hits / (float)n;
    out->development = (float)dev_hits / (float)n;
    out->development_rgb = v3_scale(dev_sum, 1.0f / (float)n);
}
