/* wp_split.c — a stem splitting into clones as Arbaro 1.9 splits it (the paper's Splitting): how many
 * clones a segment makes (0BaseSplits at the trunk's first segment, else nSegSplits with the
 * error carried from segment to segment), each clone's copy of the stem, and the split angle and
 * divergence that turn it away. Arbaro turns the clones only; the original stem keeps its
 * direction and takes the split correction (its draws still happen, in Arbaro's order). */
#include <math.h>

#include "wp_growth.h"
#include "wp_java.h"

/* A clone of stem s starting at frame trf (StemImpl.clone). */
static int clone_stem(wp_growth *g, int s, wp_frame trf)
{
    wp_stem *st = wp_stem_at(g, s);
    if (st->split_depth >= WP_MAX_SPLIT_DEPTH) {
        if (!g->failed)
            g->failed = plugin_fail(g->err, SYLVA_ERR_LIMIT,
                                    "species '%s': clones split from clones more than %d deep; lower the nSegSplits or "
                                    "nCurveRes",
                                    g->t->p->species, WP_MAX_SPLIT_DEPTH);
        return WP_NONE;
    }
    int c = wp_stem_new(g, s, st->level, trf, st->offset);
    if (c == WP_NONE) return WP_NONE;
    wp_stem *cl = wp_stem_at(g, c);
    cl->segment_length = st->segment_length;
    cl->segment_count = st->segment_count;
    cl->length = st->length;
    cl->base_radius = st->base_radius;
    cl->split_correction = st->split_correction;
    cl->prune_test = st->prune_test;
    cl->index = st->index;
    cl->is_clone = 1;
    cl->split_depth = st->split_depth + 1;
    if (!st->prune_test) {
        cl->length_child_max = st->length_child_max;
        cl->substems_per_segment = st->substems_per_segment;
        cl->substem_rotangle = st->substem_rotangle + 180;
        cl->leaves_per_segment = st->leaves_per_segment;
    }
    return c;
}

/* Turns stem x's frame trf at segment nseg by the split angle and, for a clone (s_angle > 0),
 * by the divergence about the tree's z axis; lowers its children per segment (StemImpl.split). */
static wp_frame split(wp_growth *g, wp_stem *x, wp_frame trf, double s_angle, int nseg, int nsplits)
{
    const wp_params *p = g->t->p;
    wp_level_state *lv = wp_level_of(g->t, x->level);
    int remaining_seg = x->segment_count - nseg - 1;
    double declination = acos(wp_frame_z(&trf).z) * 180 / M_PI;
    double v = wp_level_var(lv, lv->v.split_angle_v);
    double split_angle = wp_java_max(0, (lv->v.split_angle + v - declination));
    trf = wp_frame_rotx(&trf, split_angle);
    x->split_correction -= split_angle / remaining_seg;
    if (s_angle > 0) {
        double diverge;
        if (p->base_splits > 0 && x->level == 0 && nseg == 0) {
            diverge = s_angle + wp_level_var(lv, lv->v.split_angle_v);
        } else {
            double r = wp_level_var(lv, 1);
            diverge = 20 + 0.75 * (30 + fabs(declination - 90)) * pow((r + 1) / 2.0, 2);
            if (wp_level_var(lv, 1) >= 0) diverge = -diverge;
        }
        trf = wp_frame_rotaxis(&trf, diverge, wp_v(0, 0, 1));
    }
    if (!x->prune_test) x->substems_per_segment /= (float)(nsplits + 1);
    return trf;
}

int wp_stem_make_clones(wp_growth *g, int s, wp_frame trf, int nseg)
{
    const wp_params *p = g->t->p;
    wp_stem *st = wp_stem_at(g, s);
    wp_level_state *lv = wp_level_of(g->t, st->level);
    int splits;
    if (st->level == 0 && nseg == 0 && p->base_splits > 0) {
        splits = p->base_splits;
    } else {
        double seg_splits = lv->v.seg_splits;
        splits = wp_java_int(seg_splits + lv->split_error + 0.5);
        lv->split_error -= (splits - seg_splits);
    }
    if (splits < 1) return -1;
    double s_angle = (double)(360 / ((long long)splits + 1)); /* Java's integer division */
    for (int i = 0; i < splits; i++) {
        int c = clone_stem(g, s, trf);
        if (c == WP_NONE) return -1;
        wp_stem *cl = wp_stem_at(g, c);
        cl->transf = split(g, cl, trf, s_angle * (1 + i), nseg, splits);
        int out = wp_stem_make_segments(g, c, nseg + 1, cl->segment_count);
        if (g->failed) return -1;
        if (out >= 0) return out;
        int *last_next = st->clone_last == WP_NONE ? NULL : &wp_stem_at(g, st->clone_last)->next;
        wp_list_append(&st->clone_first, &st->clone_last, last_next, c);
    }
    split(g, st, trf, 0, nseg, splits);
    return -1;
}
