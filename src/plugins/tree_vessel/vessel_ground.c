/* vessel_ground.c — the soft floor under a weeping tree. */
#include "vessel_ground.h"

#include <math.h>
#include <stdlib.h>

#include "vessel_leaves.h"

static vessel_vec tip_of(const vessel_branch *b) { return vv_madd(b->base, b->frame.c[1], b->length); }

/* The soft floor: z below the knee lifted toward c, never below it. */
static double lift(double z, double c, double knee)
{
    double soft = knee - c;
    return z >= knee ? z : c + soft * (1.0 - tanh((knee - z) / soft));
}

double vessel_lowest_hanging_tip(const vessel_tree *t)
{
    double low = INFINITY;
    for (uint32_t i = 0; i < t->n; i++) {
        const vessel_branch *b = &t->branches[i];
        if (b->frame.c[1].z < 0) low = fmin(low, tip_of(b).z);
    }
    return low;
}

double vessel_ground_clearance(const vessel_tree *t, const vessel_params *p)
{
    double radius = 0, leaf = 0;
    for (uint32_t i = 0; i < t->n; i++) {
        const vessel_branch *b = &t->branches[i];
        if (b->frame.c[1].z < 0) radius = fmax(radius, 0.5 * b->diameter);
        if (b->terminal && p->leaf_density) leaf = fmax(leaf, vessel_leaf_side(b, p));
    }
    return VESSEL_GROUND_GAP + radius + leaf;
}

/* Turns b's frame so that its axis runs along d, by the least rotation. */
static void align_axis(vessel_branch *b, vessel_vec d)
{
    vessel_vec a = b->frame.c[1], n = vv_unit(d);
    vessel_vec u = vv_cross(a, n);
    double s = vv_len(u), c = vv_dot(a, n);
    if (s < 1e-15) return;
    double angle = atan2(s, c);
    u = vv_scale(u, 1.0 / s);
    for (int k = 0; k < 3; k++) b->frame.c[k] = vv_rotate(b->frame.c[k], u, angle);
}

int vessel_hang_above_ground(vessel_tree *t, const vessel_params *p, plugin_err *err)
{
    double c = vessel_ground_clearance(t, p), knee = c + VESSEL_GROUND_SOFT;
    if (!t->n || vessel_lowest_hanging_tip(t) >= c) return 0;
    vessel_vec *work = malloc(2 * (size_t)t->n * sizeof *work); /* owned here: offsets, new tips */
    if (!work) return plugin_fail_key(err, SYLVA_ERR_NOMEM, NULL, NULL, "out of memory laying out %u segments", t->n);
    vessel_vec *offset = work, *tip = work + t->n;
    for (uint32_t i = 0; i < t->n; i++) {
        const vessel_branch *b = &t->branches[i];
        offset[i] = b->mother < 0 ? vv(0, 0, 0) : vv_sub(b->base, tip_of(&t->branches[b->mother]));
    }
    /* Mothers come first in the list: each base follows its mother's new tip. */
    t->height = 0;
    for (uint32_t i = 0; i < t->n; i++) {
        vessel_branch *b = &t->branches[i];
        vessel_vec base = b->mother < 0 ? b->base : vv_add(tip[b->mother], offset[i]);
        vessel_vec d = vv_scale(b->frame.c[1], b->length);
        tip[i] = vv_add(base, d);
        if (d.z < 0) { /* hanging: onto the soft floor */
            tip[i].z = lift(tip[i].z, c, knee);
            d = vv_sub(tip[i], base);
            align_axis(b, d);
            b->length = vv_len(d);
        }
        b->base = base;
        if (b->mother >= 0) b->bark_v = vessel_bark_v_tip(&t->branches[b->mother]);
        if (tip[i].z > t->height) t->height = tip[i].z;
    }
    free(work);
    return 0;
}
