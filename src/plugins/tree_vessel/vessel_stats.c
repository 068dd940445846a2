/* vessel_stats.c — a vessel tree's figures. */
#include "vessel_stats.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "box_count.h"
#include "plugin_host.h"

/* Where segment b's axis ends, tree frame. */
static vessel_vec segment_tip(const vessel_branch *b)
{
    const vessel_vec *a = &b->frame.c[1];
    return (vessel_vec){b->base.x + a->x * b->length, b->base.y + a->y * b->length, b->base.z + a->z * b->length};
}

int vessel_stats_measure(const vessel_tree *t, const vessel_mesh *m, sylva_tree_stats *st)
{
    /* The list has every mother before her children, so depths fill in one pass. */
    uint32_t *depth = malloc((t->n ? t->n : 1) * sizeof *depth); /* owned here */
    if (!depth) return -1;
    st->recursion = 0, st->symbols = 0, st->segments = 0, st->branches = 0;
    st->law_dimension = 0, st->target_branches = 0;
    double lo_x = DBL_MAX, lo_z = DBL_MAX, hi_x = -DBL_MAX, hi_z = -DBL_MAX;
    for (uint32_t i = 0; i < t->n; i++) {
        const vessel_branch *b = &t->branches[i];
        depth[i] = b->mother < 0 ? 1 : depth[b->mother] + 1;
        if (depth[i] > st->recursion) st->recursion = depth[i];
        if (!b->drawn) continue;
        st->segments++;
        if (!b->is_main || b->mother < 0) st->branches++; /* an axis starts at the trunk and each lateral child */
        vessel_vec tip = segment_tip(b);
        lo_x = fmin(lo_x, fmin(b->base.x, tip.x)), hi_x = fmax(hi_x, fmax(b->base.x, tip.x));
        lo_z = fmin(lo_z, fmin(b->base.z, tip.z)), hi_z = fmax(hi_z, fmax(b->base.z, tip.z));
    }
    free(depth);
    st->leaves = m->leaf_triangles / 2; /* a leaf is a quad */
    st->triangles = m->nt;
    plugin_tree_stats_bounds(st, m->pos, m->nv);
    st->height = m->top;
    st->box_dimension = 0;
    if (!st->segments) return 0;
    double w = hi_x - lo_x, h = hi_z - lo_z;
    if (!(w > 0 || h > 0)) return 0; /* the wood is a point: no silhouette */
    box_raster r;
    if (box_silhouette_init(&r, lo_x, lo_z, w, h)) return -1;
    for (uint32_t i = 0; i < t->n; i++) {
        const vessel_branch *b = &t->branches[i];
        if (!b->drawn) continue;
        vessel_vec tip = segment_tip(b);
        box_raster_line(&r, b->base.x, b->base.z, tip.x, tip.z, 0.25 * (b->diameter + b->tip_diameter));
    }
    st->box_dimension = box_silhouette_dimension(&r);
    box_raster_free(&r);
    return 0;
}
