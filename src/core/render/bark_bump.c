/* bark_bump.c — bark's shading normal from its texture's luminance gradient (bark_bump.h). */
#include "render/bark_bump.h"

#include <math.h>

#include "geometry/texture_lookup.h"

static float texel_luminance(const texture *tx, float u, float v)
{
    float c[4];
    texture_sample(tx, u, v, c);
    return 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
}

static vec3 vertex(const float *a, uint32_t i) { return v3(a[i * 3], a[i * 3 + 1], a[i * 3 + 2]); }

void bark_bump(const scene *s, const mesh *m, uint32_t t, const xform3x4 *xf, hit_info *h)
{
    const material *mat = h->mat;
    if (h->kind != GEOM_PROTOTYPE || mat->bsdf != SYLVA_BSDF_LAMBERT || mat->texture < 0 || mat->alpha_mask) return;
    const texture *tx = &s->textures[mat->texture];
    const uint32_t *k = m->tri + (size_t)t * 3;
    vec3 e1 = v3_sub(vertex(m->pos, k[1]), vertex(m->pos, k[0])), e2 = v3_sub(vertex(m->pos, k[2]), vertex(m->pos, k[0]));
    float du1 = m->uv[k[1] * 2] - m->uv[k[0] * 2], dv1 = m->uv[k[1] * 2 + 1] - m->uv[k[0] * 2 + 1];
    float du2 = m->uv[k[2] * 2] - m->uv[k[0] * 2], dv2 = m->uv[k[2] * 2 + 1] - m->uv[k[0] * 2 + 1];
    float det = du1 * dv2 - du2 * dv1;
    if (!(fabsf(det) > 1e-12f)) return;
    /* dp/du and dp/dv from e1 = dpdu du1 + dpdv dv1, e2 = dpdu du2 + dpdv dv2 */
    vec3 dpdu = v3_scale(v3_sub(v3_scale(e1, dv2), v3_scale(e2, dv1)), 1.0f / det);
    vec3 dpdv = v3_scale(v3_sub(v3_scale(e2, du1), v3_scale(e1, du2)), 1.0f / det);
    if (xf) dpdu = xf_vector(xf, dpdu), dpdv = xf_vector(xf, dpdv);
    float len_u = v3_len(dpdu);
    if (!(len_u > 0.0f) || !(v3_len(dpdv) > 0.0f)) return;
    /* h = slope * L * (texel width along u): h_u = slope |dpdu| dL/dtexel_u, h_v likewise with
     * the texel count along v */
    float su = BARK_BUMP_REACH / (float)tx->width, sv = BARK_BUMP_REACH / (float)tx->height;
    float dl_u = (texel_luminance(tx, h->u + su, h->v) - texel_luminance(tx, h->u - su, h->v)) / (2.0f * BARK_BUMP_REACH);
    float dl_v = (texel_luminance(tx, h->u, h->v + sv) - texel_luminance(tx, h->u, h->v - sv)) / (2.0f * BARK_BUMP_REACH);
    float hu = BARK_BUMP_SLOPE * len_u * dl_u, hv = BARK_BUMP_SLOPE * len_u * dl_v * (float)tx->height / (float)tx->width;
    vec3 base = v3_cross(dpdu, dpdv);
    float area = v3_len(base), sign = v3_dot(base, h->ns) < 0.0f ? -1.0f : 1.0f;
    vec3 tilt = v3_add(v3_scale(v3_cross(h->ns, dpdv), hu), v3_scale(v3_cross(dpdu, h->ns), hv));
    vec3 n = v3_norm(v3_add(v3_scale(h->ns, area), v3_scale(tilt, sign)));
    /* stay on the interpolated normal's side of the geometric surface */
    vec3 ng = v3_dot(h->ng, h->ns) < 0.0f ? v3_scale(h->ng, -1.0f) : h->ng;
    float c = v3_dot(n, ng);
    if (c < BARK_BUMP_MIN_COSINE) n = v3_norm(v3_madd(n, ng, BARK_BUMP_MIN_COSINE - c));
    if (v3_dot(n, n) > 0.5f) h->ns = n;
}
