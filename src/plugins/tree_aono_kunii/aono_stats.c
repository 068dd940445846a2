/* aono_stats.c — an Aono–Kunii tree's figures. */
#include "aono_stats.h"

#include <float.h>
#include <math.h>

#include "box_count.h"
#include "plugin_host.h"

int aono_stats_measure(const aono_skeleton *s, const aono_mesh_buffer *b, int32_t leaf, sylva_tree_stats *st)
{
    st->recursion = s->levels, st->symbols = 0, st->segments = s->n, st->branches = 0;
    st->law_dimension = 0, st->target_branches = 0;
    double lo_x = DBL_MAX, lo_z = DBL_MAX, hi_x = -DBL_MAX, hi_z = -DBL_MAX;
    for (uint32_t i = 0; i < s->n; i++) {
        const aono_segment *g = &s->seg[i];
        if (!g->continues) st->branches++; /* the trunk, and each child that starts an axis of its own */
        lo_x = fmin(lo_x, fmin(g->base[0], g->tip[0])), hi_x = fmax(hi_x, fmax(g->base[0], g->tip[0]));
        lo_z = fmin(lo_z, fmin(g->base[2], g->tip[2])), hi_z = fmax(hi_z, fmax(g->base[2], g->tip[2]));
    }
    uint64_t leaf_triangles = 0;
    for (uint32_t t = 0; t < b->nt; t++) leaf_triangles += leaf >= 0 && b->mat[t] == leaf;
    st->leaves = leaf_triangles / 2; /* a leaf is a quad */
    st->triangles = b->nt;
    plugin_tree_stats_bounds(st, b->pos, b->nv);
    st->height = b->nv ? fmax(0.0, st->bbox_max[2]) : 0;
    st->box_dimension = 0;
    double w = hi_x - lo_x, h = hi_z - lo_z;
    if (!s->n || !(w > 0 || h > 0)) return 0; /* no wood, or a point: no silhouette */
    box_raster r;
    if (box_silhouette_init(&r, lo_x, lo_z, w, h)) return -1;
    for (uint32_t i = 0; i < s->n; i++) {
        const aono_segment *g = &s->seg[i];
        box_raster_line(&r, g->base[0], g->base[2], g->tip[0], g->tip[2], 0.5 * (g->radius_base + g->radius_tip));
    }
    st->box_dimension = box_silhouette_dimension(&r);
    box_raster_free(&r);
    return 0;
}
