/* wp_children.c — what a segment bears, as Arbaro 1.9's StemImpl places it: child stems spread
 * along the segment (the paper's Child stems: their number from the stems per segment with the error
 * carried on, their down and rotation angles, Arbaro's BranchDist), and on the last stem level
 * the leaves (Leaves), along the segment or, for negative Leaves, in a fan at the stem's tip, each
 * turned toward the light (Leaf orientation, Arbaro's LeafBend). */
#include <math.h>

#include "wp_growth.h"
#include "wp_java.h"

double wp_next_rotation(double *rotangle, wp_level_state *lv)
{
    if (lv->v.rotate >= 0) {
        double v = wp_level_var(lv, lv->v.rotate_v);
        *rotangle = fmod(*rotangle + lv->v.rotate + v + 360, 360);
        return *rotangle;
    }
    if (fabs(*rotangle) != 1) *rotangle = 1;
    *rotangle = -*rotangle;
    double v = wp_level_var(lv, lv->v.rotate_v);
    return *rotangle * (180 + lv->v.rotate + v);
}

wp_frame wp_stem_child_direction(wp_growth *g, wp_stem *st, wp_frame trf, double offset)
{
    const wp_params *p = g->t->p;
    wp_level_state *child = wp_level_of(g->t, st->level + 1);
    double rotangle = wp_next_rotation(&st->substem_rotangle, child);
    double downangle;
    if (child->v.down_angle_v >= 0) {
        double v = wp_level_var(child, child->v.down_angle_v);
        downangle = child->v.down_angle + v;
    } else {
        double len = st->level == 0 ? st->length * (1 - p->base_size) : st->length;
        downangle = child->v.down_angle +
                    child->v.down_angle_v * (1 - 2 * wp_shape_ratio(g->t, (st->length - offset) / len, 0));
    }
    return wp_frame_rotxz(&trf, downangle, rotangle);
}

/* Appends stem c to stem s's children. */
static void link_child(wp_growth *g, wp_stem *st, int c)
{
    int *last_next = st->child_last == WP_NONE ? NULL : &wp_stem_at(g, st->child_last)->next;
    wp_list_append(&st->child_first, &st->child_last, last_next, c);
    st->n_children++;
}

/* Where the segment's children start (offs) and how many it bears per segment, or 0 when the
 * segment lies in the trunk's bare base. */
static int children_span(const wp_growth *g, const wp_stem *st, const wp_segment *seg, double *offs, double *per_segment)
{
    const wp_params *p = g->t->p;
    if (st->level > 0) {
        *per_segment = st->substems_per_segment;
        *offs = seg->index == 0 ? wp_stem_radius(g, wp_stem_at(g, st->parent), st->offset) / st->segment_length : 0;
    } else if (seg->index * st->segment_length > p->base_size * st->length) {
        *per_segment = st->substems_per_segment;
        *offs = 0;
    } else if ((seg->index + 1) * st->segment_length <= p->base_size * st->length) {
        return 0;
    } else {
        *offs = (p->base_size * st->length - seg->index * st->segment_length) / st->segment_length;
        *per_segment = st->substems_per_segment * (1 - *offs);
    }
    return 1;
}

void wp_stem_make_substems(wp_growth *g, int s, int k)
{
    wp_stem *st = wp_stem_at(g, s);
    const wp_segment *seg = wp_segment_at(g, k);
    wp_level_state *lv = wp_level_of(g->t, st->level);
    wp_level_state *child = wp_level_of(g->t, st->level + 1);
    double offs, per_segment;
    if (!children_span(g, st, seg, &offs, &per_segment)) return;
    int count = wp_java_int(per_segment + lv->substem_error + 0.5);
    lv->substem_error -= (count - per_segment);
    if (count <= 0) return;
    double dist = (1.0 - offs) / count * child->v.branch_dist;
    double distv = dist * 0.25;
    for (int i = 0; i < count; i++) {
        double where = offs + dist / 2 + i * dist + wp_level_var(child, distv);
        double offset = (seg->index + where) * st->segment_length;
        wp_frame trf = wp_stem_child_direction(g, st, seg->transf, offset);
        trf = wp_segment_child_position(g, seg, trf, where);
        int c = wp_stem_new(g, s, st->level + 1, trf, offset);
        if (c == WP_NONE) return;
        wp_stem_at(g, c)->index = st->n_children;
        if (wp_stem_make(g, c)) {
            link_child(g, st, c);
        } else {
            if (g->failed) return;
            wp_pool_truncate(&g->stems, (size_t)c); /* not made: nothing of it is kept */
        }
    }
}

/* Leaf rotation toward the light (LeafImpl.setLeafOrientation): about the tree's z axis toward
 * the leaf's direction from the trunk, then about its own x axis upward, each by LeafBend of
 * the angle. */
static wp_frame leaf_orientation(const wp_params *p, wp_frame trf)
{
    if (p->leaf_bend == 0) return trf;
    wp_vec pos = trf.t, norm = wp_frame_y(&trf);
    double tpos = wp_atan2_deg(pos.y, pos.x);
    double tbend = tpos - wp_atan2_deg(norm.y, norm.x);
    trf = wp_frame_rotaxis(&trf, p->leaf_bend * tbend, wp_v(0, 0, 1));
    norm = wp_frame_y(&trf);
    double fbend = wp_atan2_deg(sqrt(norm.x * norm.x + norm.y * norm.y), norm.z);
    return wp_frame_rotx(&trf, p->leaf_bend * fbend);
}

static void add_leaf(wp_growth *g, wp_stem *st, wp_frame trf)
{
    if (g->failed) return;
    if (g->leaves_made >= g->max_leaves) {
        g->failed = plugin_fail(g->err, SYLVA_ERR_LIMIT,
                                "species '%s' would have more than %zu leaves (the limit max_leaves); lower Leaves or "
                                "LeafQuality, or raise the limit",
                                g->t->p->species, g->max_leaves);
        return;
    }
    wp_leaf_rec *leaf = wp_pool_push(&g->leaves);
    if (!leaf) {
        wp_growth_fail_nomem(g);
        return;
    }
    int k = (int)(g->leaves.count - 1);
    leaf->transf = leaf_orientation(g->t->p, trf);
    leaf->next = WP_NONE;
    wp_list_append(&st->leaf_first, &st->leaf_last, st->leaf_last == WP_NONE ? NULL : &wp_leaf_at(g, st->leaf_last)->next, k);
    g->leaves_made++;
}

/* Leaves spread along the segment (Leaves > 0). */
static void leaves_along(wp_growth *g, wp_stem *st, const wp_segment *seg)
{
    wp_level_state *lv = wp_level_of(g->t, st->level);
    double count = wp_java_int(st->leaves_per_segment + g->t->leaves_error + 0.5);
    g->t->leaves_error -= (count - st->leaves_per_segment);
    if (count <= 0) return;
    double offs = seg->index == 0 ? wp_stem_radius(g, wp_stem_at(g, st->parent), st->offset) / st->segment_length : 0;
    double dist = (1.0 - offs) / count;
    for (int i = 0; i < count && !g->failed; i++) {
        double where = offs + dist / 2 + i * dist + wp_level_var(lv, dist / 2);
        double loffs = (seg->index + where) * st->segment_length;
        wp_frame trf = wp_stem_child_direction(g, st, seg->transf, loffs);
        trf = wp_frame_translate(&trf, wp_vmul(wp_frame_z(&seg->transf), where * st->segment_length));
        add_leaf(g, st, trf);
    }
}

/* Leaves in a fan at the stem's tip (Leaves < 0): one in the middle for an odd count, the rest
 * in pairs to either side, Rotate apart, turned down by DownAngle. */
static void leaves_in_fan(wp_growth *g, wp_stem *st, const wp_segment *seg)
{
    wp_level_state *child = wp_level_of(g->t, st->level + 1);
    int cnt = wp_java_int(wp_stem_leaves_per_branch(g, st) + 0.5);
    wp_frame trf = wp_frame_translate(&seg->transf, wp_vmul(wp_frame_z(&seg->transf), st->segment_length));
    double distangle = child->v.rotate / cnt;
    double varangle = child->v.rotate_v / cnt;
    double downangle = child->v.down_angle;
    double vardown = child->v.down_angle_v;
    double offsetangle;
    if (cnt % 2 == 1) {
        add_leaf(g, st, trf);
        offsetangle = distangle;
    } else {
        offsetangle = distangle / 2;
    }
    for (int i = 0; i < cnt / 2 && !g->failed; i++) {
        for (int rot = 1; rot >= -1; rot -= 2) {
            double v = wp_level_var(child, varangle);
            wp_frame leaf = wp_frame_roty(&trf, rot * (offsetangle + i * distangle + v));
            double d = wp_level_var(child, vardown);
            leaf = wp_frame_rotx(&leaf, downangle + d);
            add_leaf(g, st, leaf);
        }
    }
}

void wp_stem_make_leaves(wp_growth *g, int s, int k)
{
    wp_stem *st = wp_stem_at(g, s);
    const wp_segment *seg = wp_segment_at(g, k);
    int leaves = g->t->p->leaves;
    if (leaves > 0)
        leaves_along(g, st, seg);
    else if (leaves < 0 && seg->index == st->segment_count - 1)
        leaves_in_fan(g, st, seg);
}
