/* wp_host_mesh.c — a grown tree's stems and leaves in the host's mesh form (wp_host_mesh.h). */
#include "wp_host_mesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define WP_HOST_MESH_NO_RING_ROUND 1.0 /* metres per bark tile on a level without rings */

void wp_host_mesh_bark_rounds(const wp_model *m, double round[WP_LEVELS])
{
    double sum[WP_LEVELS] = {0};
    size_t count[WP_LEVELS] = {0};
    for (size_t t = 0; t < m->n_triangles; t++) {
        unsigned l = m->level[t] < WP_LEVELS ? m->level[t] : WP_LEVELS - 1;
        for (int k = 0; k < 3; k++) {
            uint32_t a = m->triangle[t][k], b = m->triangle[t][(k + 1) % 3];
            double du = fabs(m->uv[a][0] - m->uv[b][0]), dv = fabs(m->uv[a][1] - m->uv[b][1]);
            if (!(du > 1e-9 && du < 0.5) || dv > 1e-9 * (1.0 + fabs(m->uv[a][1]))) continue;
            double d[3] = {m->vertex[a][0] - m->vertex[b][0], m->vertex[a][1] - m->vertex[b][1],
                           m->vertex[a][2] - m->vertex[b][2]};
            sum[l] += sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) / du;
            count[l]++;
        }
    }
    for (int l = 0; l < WP_LEVELS; l++) round[l] = count[l] ? sum[l] / (double)count[l] : 0.0;
}

/* Whether stem triangle t crosses the seam where u runs from its last value round the stem back
 * to 0 (the model has no seam vertex: u is i / points). */
static int wraps(const wp_model *m, size_t t)
{
    double lo = 1, hi = 0;
    for (int k = 0; k < 3; k++) {
        double u = m->uv[m->triangle[t][k]][0];
        lo = u < lo ? u : lo, hi = u > hi ? u : hi;
    }
    return hi - lo > 0.5;
}

/* Per model vertex: its stem level, and its copy at u + 1 for the triangles across the seam
 * (index into the mesh; 0 when it has none). Both arrays owned by the caller's stem_map. */
typedef struct stem_map {
    uint8_t *level;
    uint32_t *seam;
    uint32_t n_seam;
} stem_map;

static void stem_map_free(stem_map *s) { free(s->level), free(s->seam); }

static int stem_map_make(const wp_model *m, stem_map *s, plugin_err *err)
{
    size_t n = m->n_vertices ? m->n_vertices : 1;
    s->level = calloc(n, 1), s->seam = calloc(n, sizeof *s->seam), s->n_seam = 0;
    if (!s->level || !s->seam) {
        stem_map_free(s);
        return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for the map of %zu stem vertices", m->n_vertices);
    }
    for (size_t t = 0; t < m->n_triangles; t++) {
        int cross = wraps(m, t);
        for (int k = 0; k < 3; k++) {
            uint32_t v = m->triangle[t][k];
            s->level[v] = m->level[t] < WP_LEVELS ? m->level[t] : WP_LEVELS - 1;
            if (cross && m->uv[v][0] < 0.5 && !s->seam[v]) s->seam[v] = (uint32_t)m->n_vertices + s->n_seam++;
        }
    }
    return SYLVA_OK;
}

/* Room for the whole mesh; every array owned by w. */
static int mesh_alloc(wp_host_mesh *w, uint64_t nv, uint64_t nt, plugin_err *err)
{
    if (nv > WP_HOST_MESH_MAX_VERTICES || nt > WP_HOST_MESH_MAX_TRIANGLES)
        return plugin_fail(err, SYLVA_ERR_LIMIT, "the tree needs %llu vertices and %llu triangles, more than the "
                           "host's %u and %u per model", (unsigned long long)nv, (unsigned long long)nt,
                           WP_HOST_MESH_MAX_VERTICES, WP_HOST_MESH_MAX_TRIANGLES);
    w->pos = malloc((size_t)nv * 3 * sizeof(float) + 1);
    w->nrm = calloc((size_t)nv * 3 + 1, sizeof(float));
    w->uv = malloc((size_t)nv * 2 * sizeof(float) + 1);
    w->tri = malloc((size_t)nt * 3 * sizeof(uint32_t) + 1);
    w->mat = malloc((size_t)nt * sizeof(int32_t) + 1);
    if (!w->pos || !w->nrm || !w->uv || !w->tri || !w->mat) {
        wp_host_mesh_release(w);
        return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for a mesh of %llu vertices and %llu triangles",
                           (unsigned long long)nv, (unsigned long long)nt);
    }
    return SYLVA_OK;
}

static void put_vertex(wp_host_mesh *w, const double p[3], const double n[3], double u, double v)
{
    uint32_t i = w->nv++;
    for (int k = 0; k < 3; k++) w->pos[3 * i + k] = (float)p[k], w->nrm[3 * i + k] = (float)n[k];
    w->uv[2 * i] = (float)u, w->uv[2 * i + 1] = (float)v;
    if (p[2] > w->top || i == 0) w->top = p[2];
}

static void put_triangle(wp_host_mesh *w, uint32_t a, uint32_t b, uint32_t c, int32_t material)
{
    uint32_t t = w->nt++;
    w->tri[3 * t] = a, w->tri[3 * t + 1] = b, w->tri[3 * t + 2] = c;
    w->mat[t] = material;
}

/* Adds each stem triangle's area-weighted normal (its edges' cross product) to its corners'
 * normals in w (the first n_vertices of w->nrm, zero on entry). */
static void stem_normals(wp_host_mesh *w, const wp_model *m)
{
    for (size_t t = 0; t < m->n_triangles; t++) {
        const uint32_t *c = m->triangle[t];
        const double *a = m->vertex[c[0]], *b = m->vertex[c[1]], *d = m->vertex[c[2]];
        double e[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, f[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
        double n[3] = {e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]};
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < 3; j++) w->nrm[3 * c[k] + j] += (float)n[j];
    }
}

/* The stems: the model's vertices with v in bark tiles of their level, then the seam copies
 * (u + 1, the same normal), and the triangles, those across the seam on the copies. */
static void put_stems(wp_host_mesh *w, const wp_model *m, const stem_map *s, int32_t bark)
{
    double round[WP_LEVELS];
    wp_host_mesh_bark_rounds(m, round);
    for (int l = 0; l < WP_LEVELS; l++)
        if (!(round[l] > 0)) round[l] = l ? round[l - 1] : WP_HOST_MESH_NO_RING_ROUND;
    stem_normals(w, m);
    for (size_t i = 0; i < m->n_vertices; i++) {
        double n[3] = {w->nrm[3 * i], w->nrm[3 * i + 1], w->nrm[3 * i + 2]};
        put_vertex(w, m->vertex[i], n, m->uv[i][0], m->uv[i][1] / round[s->level[i]]);
    }
    for (size_t i = 0; i < m->n_vertices; i++) {
        if (!s->seam[i]) continue;
        double n[3] = {w->nrm[3 * i], w->nrm[3 * i + 1], w->nrm[3 * i + 2]};
        put_vertex(w, m->vertex[i], n, m->uv[i][0] + 1.0, m->uv[i][1] / round[s->level[i]]);
    }
    for (size_t t = 0; t < m->n_triangles; t++) {
        uint32_t c[3];
        int cross = wraps(m, t);
        for (int k = 0; k < 3; k++) {
            uint32_t v = m->triangle[t][k];
            c[k] = cross && m->uv[v][0] < 0.5 ? s->seam[v] : v;
        }
        put_triangle(w, c[0], c[1], c[2], bark);
    }
    w->stem_triangles = w->nt;
}

/* One leaf form at leaf frame f. */
static void put_leaf(wp_host_mesh *w, const wp_leaf *f, const wp_leaf_form *form, int32_t material)
{
    uint32_t first = w->nv;
    for (uint32_t i = 0; i < form->nv; i++) {
        const double *q = form->vertex[i], *r = form->normal[i];
        double p[3], n[3];
        for (int k = 0; k < 3; k++) {
            p[k] = f->origin[k] + q[0] * f->axis[0][k] + q[1] * f->axis[1][k] + q[2] * f->axis[2][k];
            n[k] = r[0] * f->axis[0][k] + r[1] * f->axis[1][k] + r[2] * f->axis[2][k];
        }
        put_vertex(w, p, n, form->uv[i][0], form->uv[i][1]);
    }
    for (uint32_t t = 0; t < form->nt; t++)
        put_triangle(w, first + form->tri[t][0], first + form->tri[t][1], first + form->tri[t][2], material);
}

int wp_host_mesh_build(const wp_model *m, const wp_leaf_form *leaf, int32_t bark, int32_t leaf_material, wp_host_mesh *out,
                  plugin_err *err)
{
    memset(out, 0, sizeof *out);
    size_t leaves = leaf && leaf->nt ? m->n_leaves : 0;
    stem_map s;
    int rc = stem_map_make(m, &s, err);
    if (rc) return rc;
    uint64_t nv = (uint64_t)m->n_vertices + s.n_seam + (uint64_t)leaves * (leaf ? leaf->nv : 0);
    uint64_t nt = (uint64_t)m->n_triangles + (uint64_t)leaves * (leaf ? leaf->nt : 0);
    if (!(rc = mesh_alloc(out, nv, nt, err))) {
        put_stems(out, m, &s, bark);
        for (size_t i = 0; i < leaves; i++) put_leaf(out, &m->leaf[i], leaf, leaf_material);
    }
    stem_map_free(&s);
    return rc;
}

void wp_host_mesh_release(wp_host_mesh *w)
{
    if (!w) return;
    free(w->pos), free(w->nrm), free(w->uv), free(w->tri), free(w->mat);
    memset(w, 0, sizeof *w);
}
