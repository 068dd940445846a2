/* vessel_structure.c — Algorithm 2 of 004 without recursion: an explicit stack of pending calls
 * drevca(g, w, S0, L0, l0, frames), visited in the algorithm's order (lateral subtree first), so
 * that a trunk of many thousand segments cannot exhaust the C stack.
 *
 * Per call (equation numbers of 004):
 *   d = k_d sqrt(S0)                                   (3.4)
 *   S1 = ceil(1 + k_s (S0 - 2)),  S2 = S0 - S1         (3.5, 3.6; k_s from 3.17)
 *   r_i = max(min(sqrt(S_i / S0), M), m)               (3.24; M, m from 3.20, 3.21)
 *   L_i = r_i L0,  l_i = k_l L_i                       (3.25, 3.26; k_l from 3.22)
 *   alpha1 = k sqrt(S2 / S0) alpha, alpha2 = alpha - alpha1     (3.7, 3.8; k = 1 - k_c at
 *                                                                g = 0, else 1: see below)
 *   alpha_x, alpha_z = w_s (1 - k_f) l0 sin(t + R)     (3.35)
 *   alpha_w = (S0 / S) w_g                             (3.36)
 * Each child's frame: the mother's frame moved to her tip, rolled by alpha_p about the axis,
 * swayed by alpha_x about x, deviated about z (main child by -alpha1 + alpha_z, lateral child
 * by +alpha2 + alpha_z: opposite sides of one plane), bent toward the ground about y x y_m
 * by alpha_m weighted with sin^2 of the inclination (3.23),
 * then bent by alpha_w about w0 = y x w (3.37, 3.38). y_m is the world's down direction read
 * through a second frame that takes every rotation but the directed wind's (004 tracks it as
 * the inverse matrix M_m^-1); the wind's w0 is read through the true frame (M_w^-1). Hanging
 * branches are then kept above the ground (vessel_ground.h). */
#include "vessel_structure.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "vessel_ground.h"

#define LOD_LEVELS 10u /* 3.28, 3.29: l_LOD = 10 leaves only the first trunk segment */

/* One pending call of Algorithm 2. */
typedef struct pending {
    vessel_vec base;
    vessel_frame frame;   /* the true frame (M_w) */
    vessel_frame gravity; /* the frame gravimorphism reads y_m from (M_m) */
    double rel_length, length, bark_v;
    uint32_t vessels, g, w;
    int32_t mother;
    uint8_t is_main;
} pending;

uint32_t vessel_grown_vessels(uint32_t vessels, double age)
{
    double s = floor(age * age * (double)vessels + 0.5);
    return s < 1.0 ? 1u : s > (double)vessels ? vessels : (uint32_t)s;
}

void vessel_tree_release(vessel_tree *t)
{
    if (!t) return;
    free(t->branches);
    memset(t, 0, sizeof *t);
}

static void orthonormalise(vessel_frame *f)
{
    f->c[1] = vv_unit(f->c[1]);
    f->c[0] = vv_unit(vv_madd(f->c[0], f->c[1], -vv_dot(f->c[0], f->c[1])));
    f->c[2] = vv_cross(f->c[0], f->c[1]);
}

/* Turns both frames by the same local rotation. */
static void turn_both(pending *c, vessel_vec axis, double angle)
{
    frame_turn(&c->frame, axis, angle);
    frame_turn(&c->gravity, axis, angle);
}

/* Gravimorphism (3.19, 3.23): bend the child toward the ground by alpha_m (degrees; negative:
 * upward) about y x y_m, y_m the down direction read through the gravity frame. sylva weights
 * the bend by sin^2 of the axis' inclination from the vertical and never turns the axis past
 * straight down (or, bending upward, straight up); docs/models/tree_vessel.md says why. */
static void bend_by_gravity(pending *c, double alpha_m)
{
    if (alpha_m == 0.0) return;
    vessel_vec down = frame_to_local(&c->gravity, vv(0, 0, -1));
    vessel_vec axis = vv_cross(vv(0, 1, 0), down);
    double s = vv_len(axis); /* sin of the inclination */
    if (s < 1e-12) return;   /* straight up or down: no plane to bend in */
    double angle = alpha_m * VESSEL_DEG * s * s;
    double to_down = acos(fmax(-1.0, fmin(1.0, down.y)));
    if (angle > to_down) angle = to_down;
    if (angle < to_down - M_PI) angle = to_down - M_PI;
    turn_both(c, vv_scale(axis, 1.0 / s), angle);
}

/* The directed wind (3.36–3.38): alpha_w (degrees) about w0 = y x w, w read in the true frame. */
static void bend_by_wind(pending *c, vessel_vec wind, double alpha_w)
{
    if (alpha_w == 0.0) return;
    vessel_vec w = frame_to_local(&c->frame, wind);
    vessel_vec axis = vv_cross(vv(0, 1, 0), w);
    double s = vv_len(axis);
    if (s < 1e-12) return;
    frame_turn(&c->frame, vv_scale(axis, 1.0 / s), alpha_w * VESSEL_DEG);
}

static int push(pending **stack, uint32_t *n, uint32_t *cap, const pending *c)
{
    if (*n == *cap) {
        uint32_t nc = *cap ? *cap * 2 : 256;
        pending *s = realloc(*stack, (size_t)nc * sizeof *s);
        if (!s) return -1;
        *stack = s, *cap = nc;
    }
    (*stack)[(*n)++] = *c;
    return 0;
}

int vessel_tree_grow(const vessel_params *p, const vessel_growth *req, vessel_tree *t,
                     plugin_err *err)
{
    vessel_tree_release(t);
    int checked = vessel_params_check(p, err);
    if (checked) return checked;
    if (!(req->age > 0.0 && req->age <= 1.0))
        return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, NULL, "age %g is outside (0, 1]; 1 is the full-grown tree",
                           req->age);

    vessel_order_table *table = malloc(sizeof *table); /* owned here, freed below */
    if (!table) return plugin_fail_key(err, SYLVA_ERR_NOMEM, NULL, NULL, "out of memory for the per-order table");
    vessel_order_table_fill(p, table);

    uint32_t S = vessel_grown_vessels(p->vessels, req->age);
    uint32_t lod = req->lod > LOD_LEVELS ? LOD_LEVELS : req->lod;
    t->vessels = S;
    t->trunk_length = req->age * req->age * p->trunk_length; /* (3.34) */
    t->w_geom = lod ? (LOD_LEVELS - lod) * (LOD_LEVELS - lod) : UINT32_MAX; /* (3.28) */
    t->w_branch = lod ? LOD_LEVELS - lod : UINT32_MAX;                      /* (3.29) */

    uint32_t cap = 2 * S - 1; /* B = 2S - 1 (3.1) is the most any level of detail keeps */
    t->branches = malloc((size_t)cap * sizeof *t->branches); /* owned by t */
    pending *stack = NULL; /* owned here */
    uint32_t depth = 0, stack_cap = 0;
    if (!t->branches) {
        free(table);
        return plugin_fail_key(err, SYLVA_ERR_NOMEM, NULL, NULL, "out of memory for %u branch segments", cap);
    }

    vessel_vec wind = vv_unit(vv(p->wind_direction[0], p->wind_direction[1], p->wind_direction[2]));
    double sway = p->wind_sway * (1.0 - p->flexibility);
    int rc = 0;

    pending first = {.base = vv(0, 0, 0), .rel_length = 1.0, .length = t->trunk_length,
                     .vessels = S, .mother = -1, .is_main = 1};
    first.frame.c[0] = vv(1, 0, 0), first.frame.c[1] = vv(0, 0, 1), first.frame.c[2] = vv(0, -1, 0);
    first.gravity = first.frame;
    if (push(&stack, &depth, &stack_cap, &first))
        rc = plugin_fail_key(err, SYLVA_ERR_NOMEM, NULL, NULL, "out of memory for the branching stack");

    while (!rc && depth > 0) {
        pending c = stack[--depth];
        /* t->n < cap: with k_s in [1/2, 1], 1 <= S2 <= S1 <= S0 - 1 at every split (3.5, 3.6),
         * so a tree of S vessels has exactly 2S - 1 segments. */
        int32_t self = (int32_t)t->n++;
        vessel_branch *b = &t->branches[self];
        *b = (vessel_branch){.base = c.base, .frame = c.frame, .length = c.length,
                             .rel_length = c.rel_length, .bark_v = c.bark_v,
                             .diameter = p->thickness * sqrt((double)c.vessels), /* (3.4) */
                             .vessels = c.vessels, .g = c.g, .w = c.w, .mother = c.mother,
                             .main_child = -1, .lateral_child = -1, .is_main = c.is_main};
        b->drawn = c.w <= t->w_branch;
        if (c.mother >= 0) {
            vessel_branch *m = &t->branches[c.mother];
            if (c.is_main) m->main_child = self;
            else m->lateral_child = self;
        }
        vessel_vec tip = vv_madd(c.base, c.frame.c[1], c.length);
        if (tip.z > t->height) t->height = tip.z;

        if (c.vessels == 1 || c.w >= t->w_geom) {
            b->terminal = 1;
            t->n_terminal++;
            continue;
        }

        const vessel_local_values *v = vessel_order_lookup(table, c.g, c.w);
        double S0 = c.vessels;
        uint32_t S1 = (uint32_t)ceil(1.0 + v->split * (S0 - 2.0)); /* (3.5) */
        uint32_t S2 = c.vessels - S1;                              /* (3.6) */
        double r1 = fmax(fmin(sqrt(S1 / S0), v->len_max), v->len_min); /* (3.24) */
        double r2 = fmax(fmin(sqrt(S2 / S0), v->len_max), v->len_min);
        double L1 = r1 * c.rel_length, L2 = r2 * c.rel_length;      /* (3.25) */
        double l1 = v->len_scale * L1, l2 = v->len_scale * L2;      /* (3.26) */
        /* (3.7) with 004's own reading of k_c (Fig. C.10): at g = 0 gravicentralism turns the
         * pair back by k_c of the main child's deviation; docs/models/tree_vessel.md. */
        double kc = c.g == 0 ? 1.0 - p->gravicentralism : 1.0;
        double a1 = kc * sqrt(S2 / S0) * v->angle;                  /* (3.7) */
        double a2 = v->angle - a1;                                  /* (3.8) */
        double ax = 0, az = 0;
        if (sway > 0 && req->uniform) {                              /* (3.35) */
            double Rx = 2 * M_PI * req->uniform(req->ctx), Rz = 2 * M_PI * req->uniform(req->ctx);
            ax = sway * c.length * sin(p->wind_time + Rx);
            az = sway * c.length * sin(p->wind_time + Rz);
        }
        double aw = S0 / (double)S * p->wind_strength;              /* (3.36) */

        b->tip_diameter = p->thickness * sqrt((double)S1);
        double tip_v = vessel_bark_v_tip(b);

        /* Both children share the roll and the sway about x. */
        pending fork = c;
        turn_both(&fork, vv(0, 1, 0), p->phyllotaxis * VESSEL_DEG);
        turn_both(&fork, vv(1, 0, 0), ax * VESSEL_DEG);

        pending kid[2]; /* 0: main, 1: lateral */
        for (int k = 0; k < 2; k++) {
            pending *d = &kid[k];
            *d = fork;
            d->base = tip;
            d->bark_v = tip_v;
            d->mother = self;
            d->is_main = k == 0;
            d->vessels = k == 0 ? S1 : S2;
            d->g = k == 0 ? c.g : c.g + 1;
            d->w = c.w + 1;
            d->rel_length = k == 0 ? L1 : L2;
            d->length = k == 0 ? l1 : l2;
            if (k == 1) /* the lateral child starts at the bark on its own side */
                d->base = vv_madd(tip, fork.frame.c[0],
                                  -0.5 * (b->tip_diameter - p->thickness * sqrt((double)S2)));
            double deviation = k == 0 ? -a1 : a2;
            turn_both(d, vv(0, 0, 1), (deviation + az) * VESSEL_DEG);
            bend_by_gravity(d, v->gravi);
            bend_by_wind(d, wind, aw);
            orthonormalise(&d->frame);
            orthonormalise(&d->gravity);
        }
        /* Lateral first (Algorithm 2 grows it before the main child): push it last. */
        if (push(&stack, &depth, &stack_cap, &kid[0]) || push(&stack, &depth, &stack_cap, &kid[1]))
            rc = plugin_fail_key(err, SYLVA_ERR_NOMEM, NULL, NULL, "out of memory for the branching stack (%u pending)", depth);
    }
    free(stack);
    free(table);
    if (!rc) rc = vessel_hang_above_ground(t, p, err);
    if (rc) vessel_tree_release(t);
    return rc;
}
