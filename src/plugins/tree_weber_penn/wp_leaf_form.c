/* wp_leaf_form.c — the species' leaf, or a card over it (wp_leaf_form.h). */
#include "wp_leaf_form.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Room for nv vertices and nt triangles in *f (emptied first). */
static int form_alloc(wp_leaf_form *f, size_t nv, size_t nt, plugin_err *err)
{
    memset(f, 0, sizeof *f);
    if (nv > UINT32_MAX || nt > UINT32_MAX)
        return plugin_fail(err, SYLVA_ERR_LIMIT, "a leaf of %zu vertices and %zu triangles is too large to draw", nv, nt);
    f->vertex = malloc((nv ? nv : 1) * sizeof *f->vertex); /* all owned by f */
    f->uv = malloc((nv ? nv : 1) * sizeof *f->uv);
    f->normal = calloc(nv ? nv : 1, sizeof *f->normal);
    f->tri = malloc((nt ? nt : 1) * sizeof *f->tri);
    if (!f->vertex || !f->uv || !f->normal || !f->tri) {
        wp_leaf_form_release(f);
        return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for a leaf of %zu vertices", nv);
    }
    f->nv = (uint32_t)nv, f->nt = (uint32_t)nt;
    return SYLVA_OK;
}

/* Each vertex's normal: the sum of its triangles' edge cross products (zero on entry). */
static void form_normals(wp_leaf_form *f)
{
    for (uint32_t t = 0; t < f->nt; t++) {
        const double *a = f->vertex[f->tri[t][0]], *b = f->vertex[f->tri[t][1]], *c = f->vertex[f->tri[t][2]];
        double e[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, g[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double n[3] = {e[1] * g[2] - e[2] * g[1], e[2] * g[0] - e[0] * g[2], e[0] * g[1] - e[1] * g[0]};
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < 3; j++) f->normal[f->tri[t][k]][j] += n[j];
    }
}

int wp_leaf_form_own(const wp_leaf_shape *shape, wp_leaf_form *out, plugin_err *err)
{
    int rc = form_alloc(out, shape->n_vertices, shape->n_triangles, err);
    if (rc) return rc;
    memcpy(out->vertex, shape->vertex, shape->n_vertices * sizeof *out->vertex);
    memcpy(out->uv, shape->uv, shape->n_vertices * sizeof *out->uv);
    memcpy(out->tri, shape->triangle, shape->n_triangles * sizeof *out->tri);
    for (size_t t = 0; t < shape->n_triangles; t++)
        for (int k = 0; k < 3; k++)
            if (out->tri[t][k] >= shape->n_vertices) {
                wp_leaf_form_release(out);
                return plugin_fail(err, SYLVA_ERR_INTERNAL, "the leaf shape's triangle %zu uses vertex %u of %zu", t,
                                   shape->triangle[t][k], shape->n_vertices);
            }
    form_normals(out);
    return SYLVA_OK;
}

int wp_leaf_texture_fit_of(const uint8_t *rgba, uint32_t size, wp_leaf_texture_fit *out)
{
    uint32_t c0 = size, c1 = 0, r0 = size, r1 = 0;
    size_t opaque = 0;
    for (uint32_t r = 0; r < size; r++)
        for (uint32_t c = 0; c < size; c++) {
            if (rgba[4 * ((size_t)r * size + c) + 3] < 128) continue;
            opaque++;
            c0 = c < c0 ? c : c0, c1 = c > c1 ? c : c1, r0 = r < r0 ? r : r0, r1 = r > r1 ? r : r1;
        }
    memset(out, 0, sizeof *out);
    if (!opaque) return -1;
    out->u0 = (double)c0 / size, out->u1 = (double)(c1 + 1) / size;
    out->v0 = 1 - (double)(r1 + 1) / size, out->v1 = 1 - (double)r0 / size;
    out->fill = (double)opaque / ((double)(c1 - c0 + 1) * (r1 - r0 + 1));
    return 0;
}

int wp_leaf_form_card(const wp_leaf_shape *shape, const wp_leaf_texture_fit *fit, wp_leaf_form *out,
                      plugin_err *err)
{
    double x0 = DBL_MAX, x1 = -DBL_MAX, z0 = DBL_MAX, z1 = -DBL_MAX;
    for (size_t i = 0; i < shape->n_vertices; i++) {
        const double *p = shape->vertex[i];
        x0 = p[0] < x0 ? p[0] : x0, x1 = p[0] > x1 ? p[0] : x1;
        z0 = p[2] < z0 ? p[2] : z0, z1 = p[2] > z1 ? p[2] : z1;
    }
    memset(out, 0, sizeof *out);
    double area = wp_leaf_shape_face_area(shape);
    if (!(x1 > x0) || !(z1 > z0) || !(area > 0))
        return plugin_fail(err, SYLVA_ERR_PARAM, "the species' leaf shape has no extent across or along the blade, "
                           "so a leaf card has no size; give leaf: own");
    if (!(fit->fill > 0) || !(fit->u1 > fit->u0) || !(fit->v1 > fit->v0))
        return plugin_fail(err, SYLVA_ERR_PARAM, "the leaf texture shows no leaf, so a card would draw nothing; give "
                           "other leaf maps or leaf: own");
    int rc = form_alloc(out, 4, 2, err);
    if (rc) return rc;
    double grow = sqrt(area / (fit->fill * (x1 - x0) * (z1 - z0)));
    double mid = 0.5 * (x0 + x1), half = 0.5 * (x1 - x0) * grow, tip = z0 + (z1 - z0) * grow;
    const double corner[4][3] = {{mid - half, 0, z0}, {mid + half, 0, z0}, {mid + half, 0, tip}, {mid - half, 0, tip}};
    const double uv[4][2] = {{fit->u0, fit->v0}, {fit->u1, fit->v0}, {fit->u1, fit->v1}, {fit->u0, fit->v1}};
    memcpy(out->vertex, corner, sizeof corner);
    memcpy(out->uv, uv, sizeof uv);
    /* Counter-clockwise seen from +y, the blade's normal (x across, z along: x cross z = -y, so
     * the corners run the other way round). */
    const uint32_t tri[2][3] = {{0, 2, 1}, {0, 3, 2}};
    memcpy(out->tri, tri, sizeof tri);
    form_normals(out);
    return SYLVA_OK;
}

void wp_leaf_form_release(wp_leaf_form *f)
{
    if (!f) return;
    free(f->vertex), free(f->uv), free(f->normal), free(f->tri);
    memset(f, 0, sizeof *f);
}
