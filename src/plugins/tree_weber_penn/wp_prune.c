/* wp_prune.c — a stem shortened to the pruning envelope as Arbaro 1.9 does it (the paper's Pruning):
 * the stem is grown as a trial (no children, no leaves) with the level's random stream saved,
 * shortened while a segment or a clone leaves the envelope, and the trial thrown away; the
 * stream and the split error are then restored, so the real stem draws what the trial drew.
 * PruneRatio blends the pruned length with the original one. */
#include "wp_growth.h"
#include "wp_java.h"

/* Drops the trial's segments, subsegments and clones (all made after the marks). */
static void drop_trial(wp_growth *g, wp_stem *st, size_t stems, size_t segments, size_t subsegments)
{
    wp_pool_truncate(&g->stems, stems);
    wp_pool_truncate(&g->segments, segments);
    wp_pool_truncate(&g->subsegments, subsegments);
    st->seg_first = st->seg_last = WP_NONE;
    st->clone_first = st->clone_last = WP_NONE;
}

static void restore(wp_level_state *lv)
{
    wp_random_restore(&lv->random, lv->saved_state);
    lv->split_error = lv->saved_split_error;
}

void wp_stem_prune(wp_growth *g, int s)
{
    wp_stem *st = wp_stem_at(g, s);
    wp_level_state *lv = wp_level_of(g->t, st->level);
    lv->saved_state = wp_random_save(&lv->random);
    lv->saved_split_error = lv->split_error;
    double splitcorr = st->split_correction;
    double origlen = st->length;
    size_t stems = (size_t)s + 1, segments = g->segments.count, subsegments = g->subsegments.count;
    st->prune_test = 1;
    int segm = wp_stem_make_segments(g, s, 0, st->segment_count);
    while (!g->failed && segm >= 0 && st->length > 0.001 * g->t->scale_tree) {
        restore(lv);
        st->split_correction = splitcorr;
        drop_trial(g, st, stems, segments, subsegments);
        double minlen = st->length / 2;
        double maxlen = st->length - origlen / 15;
        st->length = wp_java_min(wp_java_max(st->segment_length * segm, minlen), maxlen);
        st->segment_length = st->length / lv->v.curve_res;
        st->base_radius = wp_stem_base_radius(g, st);
        if (st->length > WP_MIN_STEM_LEN) segm = wp_stem_make_segments(g, s, 0, st->segment_count);
    }
    st->length = origlen - (origlen - st->length) * g->t->p->prune_ratio;
    restore(lv);
    st->split_correction = splitcorr;
    drop_trial(g, st, stems, segments, subsegments);
    st->prune_test = 0;
}
