/* shapes.c — tessellating the built-in shapes. Every shape is closed or single-sided with its
 * normal toward +Z (quad, disk) and carries uvs in [0, 1]. */
#include "scene_build/shapes.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int build_box(const double size[3], int32_t mat, mesh *m, err_buf *err)
{
    /* 6 faces × 4 vertices with flat normals. */
    static const int axes[6][3] = {{0, 1, 2}, {0, 1, 2}, {1, 2, 0}, {1, 2, 0}, {2, 0, 1}, {2, 0, 1}};
    float pos[72], nrm[72], uv[48];
    uint32_t tri[36];
    for (int f = 0; f < 6; f++) {
        int u = axes[f][0], v = axes[f][1], w = axes[f][2];
        float sgn = (f & 1) ? -1.0f : 1.0f;
        static const float cu[4] = {-1, 1, 1, -1}, cv[4] = {-1, -1, 1, 1};
        for (int k = 0; k < 4; k++) {
            float *p = pos + (f * 4 + k) * 3, *n = nrm + (f * 4 + k) * 3;
            p[u] = (float)(cu[k] * size[u] * 0.5 * sgn);
            p[v] = (float)(cv[k] * size[v] * 0.5);
            p[w] = (float)(sgn * size[w] * 0.5);
            n[u] = n[v] = 0.0f;
            n[w] = sgn;
            uv[(f * 4 + k) * 2] = (cu[k] + 1) * 0.5f;
            uv[(f * 4 + k) * 2 + 1] = (cv[k] + 1) * 0.5f;
        }
        uint32_t b = (uint32_t)f * 4;
        uint32_t t[6] = {b, b + 1, b + 2, b, b + 2, b + 3};
        memcpy(tri + f * 6, t, sizeof t);
    }
    return mesh_append(m, pos, nrm, uv, 24, tri, NULL, mat, 12, err);
}

static int build_quad(const double size[3], int32_t mat, mesh *m, err_buf *err)
{
    float w = (float)size[0] * 0.5f, h = (float)size[1] * 0.5f;
    float pos[12] = {-w, -h, 0, w, -h, 0, w, h, 0, -w, h, 0};
    float nrm[12] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    float uv[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
    return mesh_append(m, pos, nrm, uv, 4, tri, NULL, mat, 2, err);
}

static int build_disk(double radius, uint32_t segments, int32_t mat, mesh *m, err_buf *err)
{
    if (segments < 3) segments = 3;
    uint32_t nv = segments + 1;
    float *pos = malloc((size_t)nv * 3 * sizeof(float)), *uv = malloc((size_t)nv * 2 * sizeof(float));
    float *nrm = malloc((size_t)nv * 3 * sizeof(float));
    uint32_t *tri = malloc((size_t)segments * 3 * sizeof(uint32_t));
    int rc = -1;
    if (!pos || !uv || !nrm || !tri) {
        err_nomem(err, "out of memory building a disk");
        goto done;
    }
    for (uint32_t k = 0; k < nv; k++) nrm[k * 3] = 0, nrm[k * 3 + 1] = 0, nrm[k * 3 + 2] = 1;
    pos[0] = pos[1] = pos[2] = 0.0f;
    uv[0] = uv[1] = 0.5f;
    for (uint32_t k = 0; k < segments; k++) {
        double a = 2.0 * M_PI * k / segments;
        pos[(k + 1) * 3] = (float)(radius * cos(a));
        pos[(k + 1) * 3 + 1] = (float)(radius * sin(a));
        pos[(k + 1) * 3 + 2] = 0.0f;
        uv[(k + 1) * 2] = (float)(0.5 + 0.5 * cos(a));
        uv[(k + 1) * 2 + 1] = (float)(0.5 + 0.5 * sin(a));
        tri[k * 3] = 0, tri[k * 3 + 1] = k + 1, tri[k * 3 + 2] = (k + 1) % segments + 1;
    }
    rc = mesh_append(m, pos, nrm, uv, nv, tri, NULL, mat, segments, err);
done:
    free(pos), free(uv), free(nrm), free(tri);
    return rc;
}

/* Icosphere: an icosahedron subdivided `level` times, vertices pushed onto the sphere. Edge
 * midpoints are shared through a per-level edge table keyed by the smaller vertex. */
static int build_sphere(double radius, uint32_t level, int32_t mat, mesh *m, err_buf *err)
{
    if (level > SHAPE_MAX_SUBDIVISIONS)
        return err_set(err, "sphere subdivisions %u exceed the limit %u", level, SHAPE_MAX_SUBDIVISIONS);
    const double t = (1.0 + sqrt(5.0)) / 2.0;
    static const int faces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                     {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                     {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                     {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    double base[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                          {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    size_t nt = 20, nv = 12;
    size_t max_t = 20u << (2 * level), max_v = 10u * (1u << (2 * level)) + 2;
    double *v = malloc(max_v * 3 * sizeof(double));
    uint32_t *f = malloc(max_t * 3 * sizeof(uint32_t)), *g = malloc(max_t * 3 * sizeof(uint32_t));
    uint32_t *edge_key = NULL, *edge_mid = NULL;
    float *pos = NULL, *uv = NULL;
    int rc = -1;
    if (!v || !f || !g) goto oom;
    for (int i = 0; i < 12; i++) memcpy(v + i * 3, base[i], sizeof base[i]);
    for (int i = 0; i < 20; i++)
        for (int k = 0; k < 3; k++) f[i * 3 + k] = (uint32_t)faces[i][k];
    for (uint32_t l = 0; l < level; l++) {
        /* open-addressing table of edges (a < b) → midpoint vertex */
        size_t cap = 1;
        while (cap < nt * 4) cap <<= 1;
        free(edge_key), free(edge_mid);
        edge_key = malloc(cap * 2 * sizeof(uint32_t));
        edge_mid = malloc(cap * sizeof(uint32_t));
        if (!edge_key || !edge_mid) goto oom;
        memset(edge_key, 0xff, cap * 2 * sizeof(uint32_t));
        for (size_t i = 0; i < nt; i++) {
            uint32_t c[3], *tri3 = f + i * 3;
            for (int e = 0; e < 3; e++) {
                uint32_t a = tri3[e], b = tri3[(e + 1) % 3];
                if (a > b) { uint32_t x = a; a = b; b = x; }
                size_t h = ((size_t)a * 2654435761u ^ (size_t)b * 40503u) & (cap - 1);
                while (edge_key[h * 2] != UINT32_MAX && (edge_key[h * 2] != a || edge_key[h * 2 + 1] != b))
                    h = (h + 1) & (cap - 1);
                if (edge_key[h * 2] == UINT32_MAX) {
                    edge_key[h * 2] = a, edge_key[h * 2 + 1] = b;
                    for (int d = 0; d < 3; d++) v[nv * 3 + d] = 0.5 * (v[a * 3 + d] + v[b * 3 + d]);
                    edge_mid[h] = (uint32_t)nv++;
                }
                c[e] = edge_mid[h];
            }
            uint32_t q[12] = {tri3[0], c[0], c[2], tri3[1], c[1], c[0], tri3[2], c[2], c[1], c[0], c[1], c[2]};
            memcpy(g + i * 12, q, sizeof q);
        }
        nt *= 4;
        uint32_t *x = f; f = g; g = x;
    }
    pos = malloc(nv * 3 * sizeof(float));
    uv = malloc(nv * 2 * sizeof(float));
    if (!pos || !uv) goto oom;
    for (size_t i = 0; i < nv; i++) {
        double *p = v + i * 3, l = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        for (int d = 0; d < 3; d++) pos[i * 3 + d] = (float)(p[d] / l * radius);
        uv[i * 2] = (float)(0.5 + atan2(p[1], p[0]) / (2 * M_PI));
        uv[i * 2 + 1] = (float)(0.5 + asin(p[2] / l) / M_PI);
    }
    rc = mesh_append(m, pos, NULL, uv, (uint32_t)nv, f, NULL, mat, (uint32_t)nt, err);
    goto done;
oom:
    err_nomem(err, "out of memory building a sphere with %u subdivisions", level);
done:
    free(v), free(f), free(g), free(edge_key), free(edge_mid), free(pos), free(uv);
    return rc;
}

static int build_inline(const shape_spec *s, int32_t mat, mesh *m, err_buf *err)
{
    uint32_t nv = s->n_vertices, nt = s->n_triangles;
    float *pos = malloc((size_t)nv * 3 * sizeof(float) + 1), *uv = NULL;
    uint32_t *tri = malloc((size_t)nt * 3 * sizeof(uint32_t) + 1);
    int rc = -1;
    if (!pos || !tri) goto oom;
    for (size_t i = 0; i < (size_t)nv * 3; i++) pos[i] = (float)s->vertices[i];
    for (size_t i = 0; i < (size_t)nt * 3; i++) {
        double k = s->triangles[i];
        if (!(k >= 0 && k < nv && k == floor(k))) {
            err_set(err, "triangle %zu refers to vertex %g; valid indices are 0 to %u", i / 3, k, nv - 1);
            goto done;
        }
        tri[i] = (uint32_t)k;
    }
    if (s->n_uvs) {
        uv = malloc((size_t)nv * 2 * sizeof(float));
        if (!uv) goto oom;
        for (size_t i = 0; i < (size_t)nv * 2; i++) uv[i] = (float)s->uvs[i];
    }
    rc = mesh_append(m, pos, NULL, uv, nv, tri, NULL, mat, nt, err);
    goto done;
oom:
    err_nomem(err, "out of memory building an inline mesh");
done:
    free(pos), free(uv), free(tri);
    return rc;
}

int shape_build(const shape_spec *s, int32_t mat, mesh *m, err_buf *err)
{
    switch (s->kind) {
    case SHAPE_BOX: return build_box(s->size, mat, m, err);
    case SHAPE_QUAD: return build_quad(s->size, mat, m, err);
    case SHAPE_DISK: return build_disk(s->radius, s->subdivisions ? s->subdivisions : 32, mat, m, err);
    case SHAPE_SPHERE: return build_sphere(s->radius, s->subdivisions, mat, m, err);
    case SHAPE_MESH: return build_inline(s, mat, m, err);
    }
    return err_set(err, "unknown shape kind %d", (int)s->kind);
}
