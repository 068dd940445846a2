/* mesh.c — growable triangle meshes. */
#include "scene/mesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

mesh *mesh_new(void) { return calloc(1, sizeof(mesh)); }

void mesh_free(mesh *m)
{
    if (!m) return;
    free(m->pos);
    free(m->nrm);
    free(m->uv);
    free(m->tri);
    free(m->mat);
    free(m);
}

static int grow_vertices(mesh *m, uint32_t need)
{
    if (need <= m->cap_v) return 0;
    uint32_t cap = m->cap_v ? m->cap_v : 256;
    while (cap < need) cap = cap > MESH_MAX_VERTICES / 2 ? MESH_MAX_VERTICES : cap * 2;
    float *p = realloc(m->pos, ((size_t)cap * 3 + 4) * sizeof(float));
    if (!p) return -1;
    m->pos = p;
    float *n = realloc(m->nrm, (size_t)cap * 3 * sizeof(float));
    if (!n) return -1;
    m->nrm = n;
    float *t = realloc(m->uv, (size_t)cap * 2 * sizeof(float));
    if (!t) return -1;
    m->uv = t;
    m->cap_v = cap;
    return 0;
}

static int grow_triangles(mesh *m, uint32_t need)
{
    if (need <= m->cap_t) return 0;
    uint32_t cap = m->cap_t ? m->cap_t : 256;
    while (cap < need) cap = cap > MESH_MAX_TRIANGLES / 2 ? MESH_MAX_TRIANGLES : cap * 2;
    uint32_t *t = realloc(m->tri, (size_t)cap * 3 * sizeof(uint32_t));
    if (!t) return -1;
    m->tri = t;
    int32_t *k = realloc(m->mat, (size_t)cap * sizeof(int32_t));
    if (!k) return -1;
    m->mat = k;
    m->cap_t = cap;
    return 0;
}

/* Area-weighted vertex normals for the vertices [v0, v0 + nv) from triangles [t0, t0 + nt). */
static void smooth_normals(mesh *m, uint32_t v0, uint32_t nv, uint32_t t0, uint32_t nt)
{
    float *n = m->nrm + (size_t)v0 * 3;
    memset(n, 0, (size_t)nv * 3 * sizeof(float));
    for (uint32_t t = t0; t < t0 + nt; t++) {
        const uint32_t *k = m->tri + (size_t)t * 3;
        const float *a = m->pos + (size_t)k[0] * 3, *b = m->pos + (size_t)k[1] * 3,
                    *c = m->pos + (size_t)k[2] * 3;
        float e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        float e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        float f[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                      e1[0] * e2[1] - e1[1] * e2[0]};
        for (int j = 0; j < 3; j++)
            for (int d = 0; d < 3; d++) m->nrm[(size_t)k[j] * 3 + d] += f[d];
    }
    for (uint32_t v = 0; v < nv; v++) {
        float *p = n + (size_t)v * 3;
        float l = sqrtf(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        if (l > 0.0f) p[0] /= l, p[1] /= l, p[2] /= l;
        else p[0] = 0.0f, p[1] = 0.0f, p[2] = 1.0f;
    }
}

int mesh_append(mesh *m, const float *pos, const float *nrm, const float *uv, uint32_t nv,
                const uint32_t *tri, const int32_t *mat, int32_t default_mat, uint32_t nt,
                err_buf *err)
{
    if (nv > MESH_MAX_VERTICES - m->nv)
        return err_fail(err, ERR_LIMIT, "mesh would exceed %u vertices (the per-mesh limit)", MESH_MAX_VERTICES);
    if (nt > MESH_MAX_TRIANGLES - m->nt)
        return err_fail(err, ERR_LIMIT, "mesh would exceed %u triangles (the per-mesh limit)", MESH_MAX_TRIANGLES);
    if ((nv && !pos) || (nt && !tri)) return err_set(err, "mesh_append: positions or triangles missing");
    for (size_t i = 0; i < (size_t)nt * 3; i++)
        if (tri[i] >= nv)
            return err_set(err, "mesh_append: triangle %zu uses vertex %u, but only %u were given",
                           i / 3, tri[i], nv);
    for (size_t i = 0; i < (size_t)nv * 3; i++)
        if (!isfinite(pos[i])) return err_set(err, "mesh_append: vertex %zu is not finite", i / 3);
    if (grow_vertices(m, m->nv + nv) || grow_triangles(m, m->nt + nt))
        return err_nomem(err, "out of memory growing a mesh to %u vertices, %u triangles",
                       m->nv + nv, m->nt + nt);
    uint32_t v0 = m->nv, t0 = m->nt;
    memcpy(m->pos + (size_t)v0 * 3, pos, (size_t)nv * 3 * sizeof(float));
    memset(m->pos + (size_t)(v0 + nv) * 3, 0, 4 * sizeof(float));
    if (uv) memcpy(m->uv + (size_t)v0 * 2, uv, (size_t)nv * 2 * sizeof(float));
    else memset(m->uv + (size_t)v0 * 2, 0, (size_t)nv * 2 * sizeof(float));
    for (size_t i = 0; i < (size_t)nt * 3; i++) m->tri[(size_t)t0 * 3 + i] = tri[i] + v0;
    for (uint32_t t = 0; t < nt; t++) m->mat[t0 + t] = mat ? mat[t] : default_mat;
    m->nv += nv;
    m->nt += nt;
    if (nrm) {
        for (uint32_t v = 0; v < nv; v++) {
            const float *s = nrm + (size_t)v * 3;
            float l = sqrtf(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
            float *d = m->nrm + (size_t)(v0 + v) * 3;
            if (l > 0.0f && isfinite(l)) d[0] = s[0] / l, d[1] = s[1] / l, d[2] = s[2] / l;
            else d[0] = 0.0f, d[1] = 0.0f, d[2] = 1.0f;
        }
    } else {
        smooth_normals(m, v0, nv, t0, nt);
    }
    return 0;
}

void mesh_bounds(const mesh *m, float lo[3], float hi[3])
{
    for (int d = 0; d < 3; d++) lo[d] = hi[d] = m->nv ? m->pos[d] : 0.0f;
    for (uint32_t v = 0; v < m->nv; v++)
        for (int d = 0; d < 3; d++) {
            float x = m->pos[(size_t)v * 3 + d];
            if (x < lo[d]) lo[d] = x;
            if (x > hi[d]) hi[d] = x;
        }
}
