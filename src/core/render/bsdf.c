/* bsdf.c — Lambertian and translucent-leaf scattering with cosine-weighted sampling. */
#include "render/bsdf.h"

#include <math.h>

float bsdf_transmit_probability(const material *m, vec3 albedo)
{
    if (m->bsdf != SYLVA_BSDF_LEAF) return 0.0f;
    float r = v3_luminance(albedo), t = v3_luminance(m->transmittance);
    return r + t > 0.0f ? t / (r + t) : 0.0f;
}

vec3 bsdf_eval(const material *m, vec3 albedo, vec3 n, vec3 wo, vec3 wi, float *pdf)
{
    float c = v3_dot(n, wi);
    float pt = bsdf_transmit_probability(m, albedo);
    (void)wo;
    if (c > 0.0f) {
        *pdf = (1.0f - pt) * c * (float)M_1_PI;
        return v3_scale(albedo, (float)M_1_PI);
    }
    if (m->bsdf == SYLVA_BSDF_LEAF && c < 0.0f) {
        *pdf = pt * -c * (float)M_1_PI;
        return v3_scale(m->transmittance, (float)M_1_PI);
    }
    *pdf = 0.0f;
    return v3(0, 0, 0);
}

int bsdf_sample_dir(const material *m, vec3 albedo, vec3 n, vec3 wo, float u0, float u1, float u2,
                    bsdf_sample *out)
{
    float pt = bsdf_transmit_probability(m, albedo);
    vec3 side = n;
    if (u0 < pt) side = v3_scale(n, -1.0f);
    /* cosine-weighted hemisphere about `side` (Malley's method) */
    float r = sqrtf(u1), phi = 2.0f * (float)M_PI * u2;
    float x = r * cosf(phi), y = r * sinf(phi), z = sqrtf(fmaxf(0.0f, 1.0f - u1));
    vec3 t, b;
    v3_basis(side, &t, &b);
    out->wi = v3_norm(v3_add(v3_add(v3_scale(t, x), v3_scale(b, y)), v3_scale(side, z)));
    out->f = bsdf_eval(m, albedo, n, wo, out->wi, &out->pdf);
    return out->pdf > 0.0f;
}
