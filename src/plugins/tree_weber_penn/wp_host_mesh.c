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

/* Room for the whole mesh; every array owned by w. */
static int mesh_alloc(wp_host_mesh *w, uint64_t nv, uint64_t nt, plugin_err *err)
{
    if (nv > WP_HOST_MESH_MAX_VERTICES || nt > WP_HOST_MESH_MAX_TRIANGLES)
        return plugin_fail(err, SYLVA_ERR_LIMIT, "the tree needs %llu vertices and %llu triangles, more than the "
                           "host's %u and %u per model", (unsigned long long)nv, (unsigned long long)nt,
                           WP_HOST_MESH_MAX_VERTICES, WP_HOST_MESH_MAX_TRIANGLES);
    w->pos = malloc((size_t)nv * 3 * sizeof(float) + 1);
    w->uv = malloc((size_t)nv * 2 * sizeof(float) + 1);
    w->tri = malloc((size_t)nt * 3 * sizeof(uint32_t) + 1);
    w->mat = malloc((size_t)nt * sizeof(int32_t) + 1);
    if (!w->pos || !w->uv || !w->tri || !w->mat) {
        wp_host_mesh_release(w);
        return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for a mesh of %llu vertices and %llu triangles",
                           (unsigned long long)nv, (unsigned long long)nt);
    }
    return SYLVA_OK;
}

static void put_vertex(wp_host_mesh *w, const double p[3], double u, double v)
{
    uint32_t i = w->nv++;
    for (int k = 0; k < 3; k++) w->pos[3 * i + k] = (float)p[k];
    w->uv[2 * i] = (float)u, w->uv[2 * i + 1] = (float)v;
    if (p[2] > w->top || i == 0) w->top = p[2];
}

static void put_triangle(wp_host_mesh *w, uint32_t a, uint32_t b, uint32_t c, int32_t material)
{
    uint32_t t = w->nt++;
    w->tri[3 * t] = a, w->tri[3 * t + 1] = b, w->tri[3 * t + 2] = c;
    w->mat[t] = material;
}

/* The stems: the model's vertices with v in bark tiles of their level. */
static int put_stems(wp_host_mesh *w, const wp_model *m, int32_t bark, plugin_err *err)
{
    double round[WP_LEVELS];
    wp_host_mesh_bark_rounds(m, round);
    for (int l = 0; l < WP_LEVELS; l++)
        if (!(round[l] > 0)) round[l] = l ? round[l - 1] : WP_HOST_MESH_NO_RING_ROUND;
    uint8_t *level = calloc(m->n_vertices ? m->n_vertices : 1, 1); /* owned here; 0 when unused */
    if (!level) return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for the levels of %zu vertices", m->n_vertices);
    for (size_t t = 0; t < m->n_triangles; t++)
        for (int k = 0; k < 3; k++) level[m->triangle[t][k]] = m->level[t] < WP_LEVELS ? m->level[t] : WP_LEVELS - 1;
    for (size_t i = 0; i < m->n_vertices; i++)
        put_vertex(w, m->vertex[i], m->uv[i][0], m->uv[i][1] / round[level[i]]);
    free(level);
    for (size_t t = 0; t < m->n_triangles; t++)
        put_triangle(w, m->triangle[t][0], m->triangle[t][1], m->triangle[t][2], bark);
    w->stem_triangles = w->nt;
    return SYLVA_OK;
}

/* One leaf form at leaf frame f. */
static void put_leaf(wp_host_mesh *w, const wp_leaf *f, const wp_leaf_form *form, int32_t material)
{
    uint32_t first = w->nv;
    for (uint32_t i = 0; i < form->nv; i++) {
        const double *q = form->vertex[i];
        double p[3];
        for (int k = 0; k < 3; k++)
            p[k] = f->origin[k] + q[0] * f->axis[0][k] + q[1] * f->axis[1][k] + q[2] * f->axis[2][k];
        put_vertex(w, p, form->uv[i][0], form->uv[i][1]);
    }
    for (uint32_t t = 0; t < form->nt; t++)
        put_triangle(w, first + form->tri[t][0], first + form->tri[t][1], first + form->tri[t][2], material);
}

int wp_host_mesh_build(const wp_model *m, const wp_leaf_form *leaf, int32_t bark, int32_t leaf_material, wp_host_mesh *out,
                  plugin_err *err)
{
    memset(out, 0, sizeof *out);
    size_t leaves = leaf && leaf->nt ? m->n_leaves : 0;
    uint64_t nv = (uint64_t)m->n_vertices + (uint64_t)leaves * (leaf ? leaf->nv : 0);
    uint64_t nt = (uint64_t)m->n_triangles + (uint64_t)leaves * (leaf ? leaf->nt : 0);
    int rc = mesh_alloc(out, nv, nt, err);
    if (rc) return rc;
    if ((rc = put_stems(out, m, bark, err))) {
        wp_host_mesh_release(out);
        return rc;
    }
    for (size_t i = 0; i < leaves; i++) put_leaf(out, &m->leaf[i], leaf, leaf_material);
    return SYLVA_OK;
}

void wp_host_mesh_release(wp_host_mesh *w)
{
    if (!w) return;
    free(w->pos), free(w->uv), free(w->tri), free(w->mat);
    memset(w, 0, sizeof *w);
}
