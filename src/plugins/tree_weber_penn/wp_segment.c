/* wp_segment.c — a stem's segment cut into subsegments as Arbaro 1.9's SegmentImpl cuts it:
 * one for a plain segment; 10 around a helix for a negative CurveV (the paper's Curvature); 10
 * shrinking toward the tip for a spherical end (Taper in (1, 2]) and 20 for periodic tapering
 * (Taper > 2, the paper's Taper); 10 shrinking toward the base for the trunk's flare. Also where along the
 * segment a child stem or leaf sits (on the axis, or on the helix). */
#include <math.h>

#include "wp_growth.h"
#include "wp_java.h"

static wp_vec lower_position(const wp_segment *seg)
{
    return seg->transf.t;
}

static wp_vec upper_position(const wp_segment *seg)
{
    return wp_vadd(seg->transf.t, wp_vmul(wp_frame_z(&seg->transf), seg->length));
}

static int add_subsegment(wp_growth *g, wp_segment *seg, wp_vec pos, double rad, double dist)
{
    /* each cross-section normally brings 6 triangles or more: a tree (or a pruning trial) with
     * more sections than the limit's triangles is refused, so that stems thinner than a point
     * cannot grow without bound */
    if (g->subsegments.count >= g->max_triangles) return wp_growth_fail_triangles(g);
    wp_subsegment *sub = wp_pool_push(&g->subsegments);
    if (!sub) return wp_growth_fail_nomem(g);
    if (seg->sub_count == 0) seg->sub_first = (int)(g->subsegments.count - 1);
    seg->sub_count++;
    sub->pos = pos;
    sub->rad = rad;
    sub->dist = dist;
    return 0;
}

/* A subsegment at `pos` metres up the segment's axis, with the stem's radius there. */
static int add_on_axis(wp_growth *g, wp_segment *seg, const wp_stem *st, double pos)
{
    wp_vec dir = wp_vsub(upper_position(seg), lower_position(seg));
    double rad = wp_stem_radius(g, st, seg->index * seg->length + pos);
    return add_subsegment(g, seg, wp_vadd(lower_position(seg), wp_vmul(dir, pos / seg->length)), rad, pos);
}

static int make_even(wp_growth *g, wp_segment *seg, const wp_stem *st, int cnt)
{
    for (int i = 1; i < cnt + 1; i++)
        if (add_on_axis(g, seg, st, i * seg->length / cnt) < 0) return -1;
    return 0;
}

static int make_spherical_end(wp_growth *g, wp_segment *seg, const wp_stem *st, int cnt)
{
    for (int i = 1; i < cnt; i++)
        if (add_on_axis(g, seg, st, seg->length - seg->length / pow(2, i)) < 0) return -1;
    return add_subsegment(g, seg, upper_position(seg), seg->rad2, seg->length);
}

static int make_flare(wp_growth *g, wp_segment *seg, const wp_stem *st, int cnt)
{
    for (int i = cnt - 1; i >= 0; i--)
        if (add_on_axis(g, seg, st, seg->length / pow(2, i)) < 0) return -1;
    return 0;
}

static int make_helix(wp_growth *g, wp_segment *seg, const wp_stem *st, double curve_v, int cnt)
{
    double angle = fabs(curve_v) / 180 * M_PI;
    double rad = sqrt(1.0 / (cos(angle) * cos(angle)) - 1) * seg->length / M_PI / 2.0;
    for (int i = 1; i < cnt + 1; i++) {
        wp_vec pos = wp_v(rad * cos(2 * M_PI * i / cnt) - rad, rad * sin(2 * M_PI * i / cnt), i * seg->length / cnt);
        double srad = wp_stem_radius(g, st, seg->index * seg->length + i * seg->length / cnt);
        if (add_subsegment(g, seg, wp_frame_apply(&seg->transf, pos), srad, i * seg->length / cnt) < 0) return -1;
    }
    return 0;
}

int wp_segment_make(wp_growth *g, int k)
{
    wp_segment *seg = wp_segment_at(g, k);
    const wp_stem *st = wp_stem_at(g, seg->stem);
    const wp_level_state *lv = wp_level_of(g->t, st->level);
    int rc;
    if (lv->v.curve_v < 0)
        rc = make_helix(g, seg, st, lv->v.curve_v, 10);
    else if (lv->v.taper > 1 && lv->v.taper <= 2 && seg->index == st->segment_count - 1)
        rc = make_spherical_end(g, seg, st, 10);
    else if (lv->v.taper > 2)
        rc = make_even(g, seg, st, 20);
    else if (lv->level == 0 && g->t->p->flare != 0 && seg->index == 0)
        rc = make_flare(g, seg, st, 10);
    else
        rc = make_even(g, seg, st, 1);
    if (rc < 0) return -1;
    if (!st->prune_test) {
        for (int i = 0; i < seg->sub_count; i++)
            if (wp_subsegment_at(g, seg->sub_first + i)->rad >= 0.000001) g->rings_made++;
        if (g->rings_made > g->max_triangles / 3) return wp_growth_fail_triangles(g);
    }
    return 0;
}

wp_frame wp_segment_child_position(const wp_growth *g, const wp_segment *seg, wp_frame trf, double where)
{
    const wp_stem *st = wp_stem_at(g, seg->stem);
    if (wp_level_of(g->t, st->level)->v.curve_v >= 0)
        return wp_frame_translate(&trf, wp_vmul(wp_frame_z(&seg->transf), where * seg->length));
    /* on the helix: between the subsegments around `where` (Arbaro's integer division keeps
     * the fraction at 0 below the last one) */
    int n = seg->sub_count;
    int i = wp_java_int(where * (n - 1));
    if (i < 0) i = 0;
    if (i > n - 2) i = n - 2;
    wp_vec p1 = wp_subsegment_at(g, seg->sub_first + i)->pos;
    wp_vec p2 = wp_subsegment_at(g, seg->sub_first + i + 1)->pos;
    wp_vec pos = wp_vadd(p1, wp_vmul(wp_vsub(p2, p1), where - i / (n - 1)));
    return wp_frame_translate(&trf, wp_vsub(pos, lower_position(seg)));
}
