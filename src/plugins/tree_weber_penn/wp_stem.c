/* wp_stem.c — one stem as Arbaro 1.9's StemImpl makes it: its length and radius (the paper's
 * Length, Radius and Taper, with Arbaro's taper, flare and 0Scale), the number of children and
 * leaves it will bear, and its segments one after the other with the curvature of each (Curvature,
 * with Arbaro's random curving about the stem and the paper's Vertical attraction). Splitting is in
 * wp_split.c, children and leaves in wp_children.c, pruning in wp_prune.c. */
#include <math.h>

#include "wp_growth.h"
#include "wp_java.h"

int wp_stem_new(wp_growth *g, int grows_out_of, int level, wp_frame trf, double offset)
{
    if (g->failed) return WP_NONE;
    /* every stem kept brings triangles, and a stem begun costs its work: a species that begins
     * more stems than the limit's triangles (children too short to be kept, by the billion) is
     * refused rather than waited for */
    if (++g->stems_tried > g->max_triangles) {
        wp_growth_fail_triangles(g);
        return WP_NONE;
    }
    wp_stem *st = wp_pool_push(&g->stems);
    if (!st) {
        wp_growth_fail_nomem(g);
        return WP_NONE;
    }
    int s = (int)(g->stems.count - 1);
    st->level = level;
    st->parent = WP_NONE;
    st->cloned_from = WP_NONE;
    if (grows_out_of != WP_NONE) {
        const wp_stem *from = wp_stem_at(g, grows_out_of);
        if (from->level < level) {
            st->parent = grows_out_of;
        } else {
            st->cloned_from = grows_out_of;
            st->parent = from->parent;
        }
    }
    st->transf = trf;
    st->offset = offset;
    st->seg_first = st->seg_last = WP_NONE;
    st->child_first = st->child_last = WP_NONE;
    st->clone_first = st->clone_last = WP_NONE;
    st->leaf_first = st->leaf_last = WP_NONE;
    st->next = WP_NONE;
    return s;
}

/* The stem's length (the paper's Length): the trunk's from Scale, a first-level branch's from the tree's shape
 * ratio at its place on the trunk, deeper ones from their parent's remaining length. */
static double stem_length(wp_growth *g, wp_stem *st)
{
    const wp_params *p = g->t->p;
    if (st->level == 0) {
        wp_level_state *lv = wp_level_of(g->t, 0);
        double v = wp_level_var(lv, lv->v.length_v);
        return (lv->v.length + v) * g->t->scale_tree;
    }
    const wp_stem *parent = wp_stem_at(g, st->parent);
    if (st->level == 1) {
        double parlen = parent->length;
        double baselen = p->base_size * g->t->scale_tree;
        double ratio = (parlen - st->offset) / (parlen - baselen);
        return parlen * parent->length_child_max * wp_shape_ratio(g->t, ratio, p->shape);
    }
    return parent->length_child_max * (parent->length - 0.6 * st->offset);
}

double wp_stem_base_radius(const wp_growth *g, const wp_stem *st)
{
    const wp_params *p = g->t->p;
    if (st->level == 0) return st->length * p->ratio;
    const wp_stem *parent = wp_stem_at(g, st->parent);
    double max_radius = wp_stem_radius(g, parent, st->offset);
    double radius = parent->base_radius * pow(st->length / parent->length, p->ratio_power);
    return wp_java_min(radius, max_radius);
}

/* nTaper in (1, 3): a spherical end (1 to 2) or periodic swelling (2 to 3) of radius r at
 * relative height z (Arbaro's reading of the paper's Taper). */
static double taper_shape(const wp_stem *st, double taper, double z, double radius)
{
    double z2 = (1 - z) * st->length;
    double depth = (taper < 2 || z2 < radius) ? 1 : taper - 2;
    double z3 = taper < 2 ? z2 : fabs(z2 - 2 * radius * wp_java_int(z2 / 2 / radius + 0.5));
    if (taper > 2 || z3 < radius)
        radius = (1 - depth) * radius + depth * sqrt(radius * radius - (z3 - radius) * (z3 - radius));
    return radius;
}

double wp_stem_radius(const wp_growth *g, const wp_stem *st, double h)
{
    const wp_params *p = g->t->p;
    const wp_level_state *lv = wp_level_of(g->t, st->level);
    double z = wp_java_min(h / st->length, 1.0);
    double taper = lv->v.taper;
    double unit_taper = 0;
    if (taper <= 1)
        unit_taper = taper;
    else if (taper <= 2)
        unit_taper = 2 - taper;
    double radius = st->base_radius * (1 - unit_taper * z);
    if (taper > 1) radius = taper_shape(st, taper, z, radius);
    if (st->level == 0) {
        if (p->flare != 0) {
            double y = wp_java_max(0, 1 - 8 * z);
            double flare = 1 + p->flare * (pow(100, y) - 1) / 100.0;
            radius = radius * flare;
        }
        radius = radius * p->trunk_scale;
    }
    return radius;
}

/* The leaves a stem of the last level bears (Arbaro's reading of the paper's Leaves: Leaves scaled by the
 * LeafDistrib shape ratio at the stem's place on its parent and by LeafQuality). */
double wp_stem_leaves_per_branch(const wp_growth *g, const wp_stem *st)
{
    const wp_params *p = g->t->p;
    if (p->leaves == 0 || st->level == 0) return 0;
    const wp_stem *parent = wp_stem_at(g, st->parent);
    int leaves = p->leaves == INT_MIN ? INT_MIN : (p->leaves < 0 ? -p->leaves : p->leaves);
    return leaves * wp_shape_ratio(g->t, st->offset / parent->length, p->leaf_distrib) * p->leaf_quality;
}

/* The child stems' maximum length and count per segment (Arbaro's prepareSubstemParams, the
 * paper's Child stems). */
static void prepare_children(wp_growth *g, wp_stem *st)
{
    const wp_params *p = g->t->p;
    wp_level_state *child = wp_level_of(g->t, st->level + 1);
    double v = wp_level_var(child, child->v.length_v);
    st->length_child_max = child->v.length + v;
    double stems_max = child->v.branches;
    double count;
    if (st->level == 0) {
        count = stems_max;
        st->substems_per_segment = count / (float)st->segment_count / (1 - p->base_size);
    } else {
        const wp_stem *parent = wp_stem_at(g, st->parent);
        if (st->level == 1)
            count = wp_java_int(stems_max * (0.2 + 0.8 * st->length / parent->length / parent->length_child_max));
        else
            count = wp_java_int(stems_max * (1.0 - 0.5 * st->offset / parent->length));
        st->substems_per_segment = count / (float)st->segment_count;
    }
    st->substem_rotangle = 0;
    if (wp_level_of(g->t, st->level)->level == g->t->levels - 1)
        st->leaves_per_segment = wp_stem_leaves_per_branch(g, st) / st->segment_count;
}

int wp_stem_make(wp_growth *g, int s)
{
    if (g->failed) return 0;
    wp_stem *st = wp_stem_at(g, s);
    wp_level_state *lv = wp_level_of(g->t, st->level);
    st->segment_count = lv->v.curve_res;
    st->length = stem_length(g, st);
    st->segment_length = st->length / lv->v.curve_res;
    st->base_radius = wp_stem_base_radius(g, st);
    if (st->level > 0 && g->t->p->prune_ratio > 0) wp_stem_prune(g, s);
    if (g->failed) return 0;
    if (!(st->length > WP_MIN_STEM_LEN && st->base_radius > WP_MIN_STEM_RADIUS)) return 0;
    prepare_children(g, st);
    wp_stem_make_segments(g, s, 0, st->segment_count);
    return !g->failed;
}

/* The direction of segment nsegm from the previous one's (Arbaro's newDirection): the level's
 * curvature (with CurveBack for the upper half) plus the split correction, a random turn about
 * the stem when CurveV > 0, and the upward attraction of stems from level 2 on. */
static wp_frame new_direction(wp_growth *g, wp_stem *st, wp_frame trf, int nsegm)
{
    if (nsegm == 0) return trf;
    const wp_params *p = g->t->p;
    wp_level_state *lv = wp_level_of(g->t, st->level);
    int res = lv->v.curve_res;
    double delta;
    if (lv->v.curve_back == 0)
        delta = lv->v.curve / res;
    else if (nsegm < (res + 1) / 2)
        delta = lv->v.curve * 2 / res;
    else
        delta = lv->v.curve_back * 2 / res;
    delta += st->split_correction;
    trf = wp_frame_rotx(&trf, delta);
    if (lv->v.curve_v > 0) {
        delta = wp_level_var(lv, lv->v.curve_v) / res;
        double rho = 180 + wp_level_var(lv, 180);
        trf = wp_frame_rotaxisz(&trf, delta, rho);
    }
    if (p->attraction_up != 0 && st->level >= 2) {
        double declination = acos(wp_frame_z(&trf).z);
        double curve_up = p->attraction_up * fabs(declination * sin(declination)) / res;
        wp_vec z = wp_frame_z(&trf);
        trf = wp_frame_rotaxis(&trf, -curve_up * 180 / M_PI, wp_v(-z.y, z.x, 0));
    }
    return trf;
}

/* Whether point v lies inside the pruning envelope (the paper's Pruning). */
static int inside_envelope(const wp_growth *g, wp_vec v)
{
    const wp_params *p = g->t->p;
    double scale = g->t->scale_tree;
    double r = sqrt(v.x * v.x + v.y * v.y);
    double ratio = (scale - v.z) / (scale * (1 - p->base_size));
    return (r / scale) < (p->prune_width * wp_shape_ratio(g->t, ratio, 8));
}

/* A new segment of stem s, made with its subsegments and linked at the stem's end. */
static int add_segment(wp_growth *g, int s, int index, wp_frame trf, double rad1, double rad2)
{
    wp_segment *seg = wp_pool_push(&g->segments);
    if (!seg) return wp_growth_fail_nomem(g);
    int k = (int)(g->segments.count - 1);
    wp_stem *st = wp_stem_at(g, s);
    seg->stem = s;
    seg->index = index;
    seg->transf = trf;
    seg->rad1 = rad1;
    seg->rad2 = rad2;
    seg->length = st->segment_length;
    seg->next = WP_NONE;
    if (wp_segment_make(g, k) < 0) return -1;
    wp_list_append(&st->seg_first, &st->seg_last, st->seg_last == WP_NONE ? NULL : &wp_segment_at(g, st->seg_last)->next, k);
    return k;
}

int wp_stem_make_segments(wp_growth *g, int s, int start, int end)
{
    wp_stem *st = wp_stem_at(g, s);
    const wp_params *p = g->t->p;
    int level = wp_level_of(g->t, st->level)->level;
    wp_frame trf = st->transf;
    for (int i = start; i < end; i++) {
        if (g->failed) return -1;
        trf = new_direction(g, st, trf, i);
        double rad1 = wp_stem_radius(g, st, i * st->segment_length);
        double rad2 = wp_stem_radius(g, st, (i + 1) * st->segment_length);
        int seg = add_segment(g, s, i, trf, rad1, rad2);
        if (seg < 0) return -1;
        if (!st->prune_test && level < g->t->levels - 1) wp_stem_make_substems(g, s, seg);
        if (!st->prune_test && level == g->t->levels - 1 && p->leaves != 0) wp_stem_make_leaves(g, s, seg);
        if (g->failed) return -1;
        trf = wp_frame_translate(&trf, wp_vmul(wp_frame_z(&trf), st->segment_length));
        if (st->prune_test && !inside_envelope(g, trf.t)) return i;
        if (i < end - 1) {
            int out = wp_stem_make_clones(g, s, trf, i);
            if (out >= 0) return out;
        }
    }
    return -1;
}
