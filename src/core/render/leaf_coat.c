/* leaf_coat.c — the leaf cuticle's GGX reflection and its tabulated directional albedo
 * (leaf_coat.h). The table is built once, on first use, by a fixed quadrature: the same numbers
 * on every run and thread. */
#include "render/leaf_coat.h"

#include <math.h>
#include <pthread.h>

#define ALBEDO_BINS 33     /* E at mu = 0, 1/32, ..., 1 */
#define QUAD 96            /* QUAD x QUAD microfacet normals per entry */

static float albedo_table[ALBEDO_BINS], albedo_mean;
static pthread_once_t table_once = PTHREAD_ONCE_INIT;

float leaf_coat_fresnel(float c, float eta)
{
    c = fminf(fabsf(c), 1.0f);
    float s2 = (1.0f - c * c) / (eta * eta); /* sin^2 of the refracted angle */
    if (s2 >= 1.0f) return 1.0f;
    float ct = sqrtf(1.0f - s2);
    float rs = (c - eta * ct) / (c + eta * ct), rp = (eta * c - ct) / (eta * c + ct);
    return 0.5f * (rs * rs + rp * rp);
}

/* GGX distribution of microfacet normals at cosine ch to the macro normal. */
static float ggx_d(float ch)
{
    float a2 = LEAF_CUTICLE_ALPHA * LEAF_CUTICLE_ALPHA, d = ch * ch * (a2 - 1.0f) + 1.0f;
    return ch > 0.0f ? a2 / ((float)M_PI * d * d) : 0.0f;
}

/* Smith's Lambda for GGX at cosine c. */
static float ggx_lambda(float c)
{
    float t2 = (1.0f - c * c) / (c * c);
    return 0.5f * (sqrtf(1.0f + LEAF_CUTICLE_ALPHA * LEAF_CUTICLE_ALPHA * t2) - 1.0f);
}

/* f_spec for cosines co, ci > 0 to the normal, ch of the half vector, oh = wo.h. */
static float coat_brdf(float co, float ci, float ch, float oh)
{
    float g = 1.0f / (1.0f + ggx_lambda(co) + ggx_lambda(ci));
    return ggx_d(ch) * leaf_coat_fresnel(oh, LEAF_CUTICLE_IOR) * g / (4.0f * co * ci);
}

float leaf_coat_eval(vec3 n, vec3 wo, vec3 wi, float *pdf)
{
    float co = v3_dot(n, wo), ci = v3_dot(n, wi);
    *pdf = 0.0f;
    if (!(co > 0.0f) || !(ci > 0.0f)) return 0.0f;
    vec3 h = v3_norm(v3_add(wo, wi));
    float ch = v3_dot(n, h), oh = v3_dot(wo, h);
    if (!(oh > 0.0f)) return 0.0f;
    *pdf = ggx_d(ch) * ch / (4.0f * oh);
    return coat_brdf(co, ci, ch, oh);
}

/* The microfacet normal for (u1, u2) with density D(h) cos(h), in the frame (t, b, n). */
static vec3 sample_normal(vec3 n, float u1, float u2)
{
    float t2 = LEAF_CUTICLE_ALPHA * LEAF_CUTICLE_ALPHA * u1 / (1.0f - u1);
    float ch = 1.0f / sqrtf(1.0f + t2), sh = sqrtf(fmaxf(0.0f, 1.0f - ch * ch));
    float phi = 2.0f * (float)M_PI * u2;
    vec3 t, b;
    v3_basis(n, &t, &b);
    return v3_norm(v3_add(v3_add(v3_scale(t, sh * cosf(phi)), v3_scale(b, sh * sinf(phi))), v3_scale(n, ch)));
}

int leaf_coat_sample(vec3 n, vec3 wo, float u1, float u2, vec3 *wi)
{
    vec3 h = sample_normal(n, u1, u2);
    float oh = v3_dot(wo, h);
    if (!(oh > 0.0f)) return 0;
    *wi = v3_norm(v3_sub(v3_scale(h, 2.0f * oh), wo));
    return v3_dot(n, *wi) > 0.0f;
}

/* E(mu) by stratified sampling of h from D(h) cos(h): E = mean of f cos(i) / pdf. */
static float albedo_at(float mu)
{
    if (mu <= 0.0f) return 0.0f; /* the coat reflects nothing it cannot be reached by */
    vec3 n = v3(0, 0, 1), wo = v3(sqrtf(fmaxf(0.0f, 1.0f - mu * mu)), 0, mu);
    double sum = 0.0;
    for (int i = 0; i < QUAD; i++)
        for (int j = 0; j < QUAD; j++) {
            vec3 wi;
            if (!leaf_coat_sample(n, wo, (i + 0.5f) / QUAD, (j + 0.5f) / QUAD, &wi)) continue;
            float pdf, f = leaf_coat_eval(n, wo, wi, &pdf);
            if (pdf > 0.0f) sum += f * wi.z / pdf;
        }
    return (float)(sum / (QUAD * QUAD));
}

static void build_table(void)
{
    double mean = 0.0;
    for (int k = 0; k < ALBEDO_BINS; k++) albedo_table[k] = albedo_at((float)k / (ALBEDO_BINS - 1));
    /* E_avg = 2 integral E(mu) mu dmu of the interpolated table (leaf_coat_albedo), exactly:
     * over a bin where E runs linearly from e0 to e1, the integral is
     * (m1 - m0) (e0 (2 m0 + m1) + e1 (m0 + 2 m1)) / 6. */
    for (int k = 0; k + 1 < ALBEDO_BINS; k++) {
        double m0 = (double)k / (ALBEDO_BINS - 1), m1 = (double)(k + 1) / (ALBEDO_BINS - 1);
        mean += (m1 - m0) * (albedo_table[k] * (2 * m0 + m1) + albedo_table[k + 1] * (m0 + 2 * m1)) / 6.0;
    }
    albedo_mean = (float)(2.0 * mean);
}

float leaf_coat_albedo(float mu)
{
    pthread_once(&table_once, build_table);
    float x = fminf(fmaxf(mu, 0.0f), 1.0f) * (ALBEDO_BINS - 1);
    int k = (int)x;
    if (k >= ALBEDO_BINS - 1) return albedo_table[ALBEDO_BINS - 1];
    float f = x - (float)k;
    return albedo_table[k] + (albedo_table[k + 1] - albedo_table[k]) * f;
}

float leaf_coat_albedo_mean(void)
{
    pthread_once(&table_once, build_table);
    return albedo_mean;
}
