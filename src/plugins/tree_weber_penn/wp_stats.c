/* wp_stats.c — a Weber–Penn tree's figures (wp_stats.h). */
#include "wp_stats.h"

#include <float.h>
#include <math.h>

#include "box_count.h"
#include "plugin_host.h"

/* D_B of the stems' side view (x-z), or 0 when they have no extent. */
static int stem_dimension(const wp_model *m, double *d)
{
    double lo_x = DBL_MAX, lo_z = DBL_MAX, hi_x = -DBL_MAX, hi_z = -DBL_MAX;
    for (size_t t = 0; t < m->n_triangles; t++)
        for (int k = 0; k < 3; k++) {
            const double *p = m->vertex[m->triangle[t][k]];
            lo_x = fmin(lo_x, p[0]), hi_x = fmax(hi_x, p[0]);
            lo_z = fmin(lo_z, p[2]), hi_z = fmax(hi_z, p[2]);
        }
    *d = 0;
    double w = hi_x - lo_x, h = hi_z - lo_z;
    if (!m->n_triangles || !(w > 0 || h > 0)) return 0;
    box_raster r;
    if (box_silhouette_init(&r, lo_x, lo_z, w, h)) return -1;
    for (size_t t = 0; t < m->n_triangles; t++) {
        const double *a = m->vertex[m->triangle[t][0]], *b = m->vertex[m->triangle[t][1]];
        const double *c = m->vertex[m->triangle[t][2]];
        box_raster_triangle(&r, a[0], a[2], b[0], b[2], c[0], c[2]);
    }
    *d = box_silhouette_dimension(&r);
    box_raster_free(&r);
    return 0;
}

int wp_stats_measure(const wp_model *m, int levels, const wp_host_mesh *w, sylva_tree_stats *st)
{
    st->recursion = levels > 0 ? (uint32_t)levels : 0;
    st->symbols = 0, st->segments = 0, st->branches = 0;
    st->law_dimension = 0, st->target_branches = 0;
    for (int l = 0; l < WP_LEVELS; l++) st->segments += m->faces[l], st->branches += m->stems[l];
    st->leaves = m->n_leaves;
    st->triangles = w->nt;
    plugin_tree_stats_bounds(st, w->pos, w->nv);
    st->height = w->nv ? w->top : 0;
    return stem_dimension(m, &st->box_dimension);
}
