/* bsdf.c — Lambertian reflection, and the leaf: a rough dielectric coat (leaf_coat.h) over
 * diffuse reflection and diffuse transmission; cosine-weighted and microfacet sampling. */
#include "render/bsdf.h"

#include <math.h>

#include "render/leaf_coat.h"

float bsdf_transmit_probability(const material *m, vec3 albedo)
{
    if (m->bsdf != SYLVA_BSDF_LEAF) return 0.0f;
    float r = v3_luminance(albedo), t = v3_luminance(m->transmittance);
    return r + t > 0.0f ? t / (r + t) : 0.0f;
}

/* The share of a leaf's samples given to the coat: its reflectance E(mu_o) against what the
 * layer under it returns, (1 - E(mu_o)) (r + t), in luminance. */
static float coat_probability(const material *m, vec3 albedo, float co)
{
    float e = leaf_coat_albedo(co);
    float under = (1.0f - e) * (v3_luminance(albedo) + v3_luminance(m->transmittance));
    return e + under > 0.0f ? e / (e + under) : 0.0f;
}

static vec3 lambert_eval(vec3 albedo, vec3 n, vec3 wi, float *pdf)
{
    float c = v3_dot(n, wi);
    *pdf = c > 0.0f ? c * (float)M_1_PI : 0.0f;
    return c > 0.0f ? v3_scale(albedo, (float)M_1_PI) : v3(0, 0, 0);
}

/* The leaf: f = f_coat + (1 - E(mu_o)) (1 - E(|mu_i|)) / (pi (1 - E_avg)) times the albedo on
 * the side of wo or the transmittance on the other side. */
static vec3 leaf_eval(const material *m, vec3 albedo, vec3 n, vec3 wo, vec3 wi, float *pdf)
{
    float co = v3_dot(n, wo), ci = v3_dot(n, wi);
    float ps = coat_probability(m, albedo, co), pt = bsdf_transmit_probability(m, albedo);
    float pdf_coat, coat = leaf_coat_eval(n, wo, wi, &pdf_coat);
    float under = (1.0f - leaf_coat_albedo(co)) * (1.0f - leaf_coat_albedo(fabsf(ci))) /
                  ((float)M_PI * (1.0f - leaf_coat_albedo_mean()));
    if (ci > 0.0f) {
        *pdf = ps * pdf_coat + (1.0f - ps) * (1.0f - pt) * ci * (float)M_1_PI;
        return v3_add(v3(coat, coat, coat), v3_scale(albedo, under));
    }
    if (ci < 0.0f) {
        *pdf = (1.0f - ps) * pt * -ci * (float)M_1_PI;
        return v3_scale(m->transmittance, under);
    }
    *pdf = 0.0f;
    return v3(0, 0, 0);
}

vec3 bsdf_eval(const material *m, vec3 albedo, vec3 n, vec3 wo, vec3 wi, float *pdf)
{
    if (m->bsdf == SYLVA_BSDF_LEAF) return leaf_eval(m, albedo, n, wo, wi, pdf);
    return lambert_eval(albedo, n, wi, pdf);
}

int bsdf_sample_dir(const material *m, vec3 albedo, vec3 n, vec3 wo, float u0, float u1, float u2,
                    bsdf_sample *out)
{
    vec3 side = n;
    if (m->bsdf == SYLVA_BSDF_LEAF) {
        float ps = coat_probability(m, albedo, v3_dot(n, wo));
        if (u0 < ps) {
            if (!leaf_coat_sample(n, wo, u1, u2, &out->wi)) return 0;
            out->f = bsdf_eval(m, albedo, n, wo, out->wi, &out->pdf);
            return out->pdf > 0.0f;
        }
        /* u0 reused past the coat's share to choose between the two diffuse sides */
        if ((u0 - ps) / (1.0f - ps) < bsdf_transmit_probability(m, albedo)) side = v3_scale(n, -1.0f);
    }
    /* cosine-weighted hemisphere about `side` (Malley's method) */
    float r = sqrtf(u1), phi = 2.0f * (float)M_PI * u2;
    float x = r * cosf(phi), y = r * sinf(phi), z = sqrtf(fmaxf(0.0f, 1.0f - u1));
    vec3 t, b;
    v3_basis(side, &t, &b);
    out->wi = v3_norm(v3_add(v3_add(v3_scale(t, x), v3_scale(b, y)), v3_scale(side, z)));
    out->f = bsdf_eval(m, albedo, n, wo, out->wi, &out->pdf);
    return out->pdf > 0.0f;
}
