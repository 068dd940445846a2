/* wp_growth.c — the tree's trunks grown as Arbaro 1.9's TreeImpl.make grows them (the paper's
 * Splitting, for several trunks: 0Branches trunks, each turned by the level's rotation and down angle
 * and moved off the centre by 0BranchDist), and the growth's pools and sticky failure. */
#include <math.h>
#include <string.h>

#include "wp_growth.h"

void wp_growth_init(wp_growth *g, wp_prepared *t, size_t max_triangles, size_t max_leaves, plugin_err *err)
{
    memset(g, 0, sizeof *g);
    g->t = t;
    wp_pool_init(&g->stems, sizeof(wp_stem));
    wp_pool_init(&g->segments, sizeof(wp_segment));
    wp_pool_init(&g->subsegments, sizeof(wp_subsegment));
    wp_pool_init(&g->leaves, sizeof(wp_leaf_rec));
    g->trunk_first = g->trunk_last = WP_NONE;
    g->max_triangles = max_triangles;
    g->max_leaves = max_leaves;
    g->err = err;
}

void wp_growth_free(wp_growth *g)
{
    wp_pool_free(&g->stems);
    wp_pool_free(&g->segments);
    wp_pool_free(&g->subsegments);
    wp_pool_free(&g->leaves);
}

int wp_growth_fail_nomem(wp_growth *g)
{
    if (!g->failed)
        g->failed = plugin_fail(g->err, SYLVA_ERR_NOMEM, "out of memory while growing species '%s'", g->t->p->species);
    return g->failed;
}

int wp_growth_fail_triangles(wp_growth *g)
{
    if (!g->failed)
        g->failed = plugin_fail(g->err, SYLVA_ERR_LIMIT,
                                "species '%s' would have more than %zu stem triangles (the limit max_triangles); lower "
                                "Levels, the nBranches, nCurveRes or Smooth, or raise the limit",
                                g->t->p->species, g->max_triangles);
    return g->failed;
}

/* A trunk's direction (TreeImpl.trunkDirection): rotating trunks turn on by Rotate each,
 * alternating ones (Rotate < 0) swing to either side. */
static wp_frame trunk_direction(wp_growth *g, wp_frame trf, wp_level_state *lv)
{
    double rotangle = wp_next_rotation(&g->trunk_rotangle, lv);
    double v = wp_level_var(lv, lv->v.down_angle_v);
    return wp_frame_rotxz(&trf, lv->v.down_angle + v, rotangle);
}

int wp_growth_grow(wp_growth *g)
{
    wp_level_state *lv = wp_level_of(g->t, 0);
    wp_frame base = wp_frame_identity();
    for (int i = 0; i < lv->v.branches && !g->failed; i++) {
        wp_frame trf = trunk_direction(g, base, lv);
        double angle = wp_level_var(lv, 360);
        double dist = wp_level_var(lv, lv->v.branch_dist);
        /* Arbaro passes the angle in degrees to sin and cos, which take radians: kept */
        trf = wp_frame_translate(&trf, wp_v(dist * sin(angle), dist * cos(angle), 0));
        int s = wp_stem_new(g, WP_NONE, 0, trf, 0);
        if (s == WP_NONE) break;
        int *last_next = g->trunk_last == WP_NONE ? NULL : &wp_stem_at(g, g->trunk_last)->next;
        wp_list_append(&g->trunk_first, &g->trunk_last, last_next, s);
        wp_stem_make(g, s);
    }
    return g->failed;
}
