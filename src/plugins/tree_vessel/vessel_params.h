/* vessel_params.h — one tree species' parameters in the vessel model of 004 ch. 3: the global
 * values, the twelve control polylines of the per-order parameters (3.17–3.22), leaves, bark,
 * wind; the limits every parameter set is checked against; and the per-order values at whole
 * orders with the clamps of 3.17–3.22.
 *
 * A vessel_params is plain data (no pointers): copy it freely. */
#ifndef VESSEL_PARAMS_H
#define VESSEL_PARAMS_H

#include <stdint.h>

#include "bark_fractal.h"
#include "leaf_affine.h"
#include "plugin_err.h"
#include "vessel_polyline.h"

/* Limits (documented in docs/models/tree_vessel.md). */
#define VESSEL_MAX_VESSELS 100000u       /* S: 16 times the spruce's 6000 */
#define VESSEL_MAX_TRUNK_LENGTH 100.0    /* l0, metres */
#define VESSEL_MAX_LEAF_SIZE 5.0         /* l_l, metres */
#define VESSEL_MAX_LEAF_DENSITY 1000u    /* rho_l, leaves per terminal branch */
#define VESSEL_MAX_LEAF_SPRAY 9u         /* leaves fanned on one leaf quad */
#define VESSEL_MIN_SIDES 4u              /* n of the truncated cones (004 Fig. 3.11) */
#define VESSEL_MAX_SIDES 15u
#define VESSEL_MAX_TRIANGLES 20000000u   /* per tree model, checked before any mesh is built */
#define VESSEL_MAX_WIND 10.0             /* w_s and w_g (004's slider range) */
#define VESSEL_MAX_WIND_TIME 1000.0      /* |t| of the frozen sway, radians */

typedef enum vessel_leaf_type {
    VESSEL_LEAF_STACKED = 0,  /* pairs, one leaf on each side, all pairs in one plane */
    VESSEL_LEAF_STAGGERED,    /* one per place, sides alternating */
    VESSEL_LEAF_SPIRAL,       /* one per place, turning about the branch */
    VESSEL_LEAF_BUNCHED,      /* all at the tip */
    VESSEL_LEAF_CONIFEROUS,   /* staggered, at an acute angle to the branch */
    VESSEL_LEAF_TYPES
} vessel_leaf_type;

/* The per-order parameters, each a product of a g polyline and a w polyline. */
typedef enum vessel_local {
    VESSEL_SPLIT = 0,   /* k_s: share of the vessels the main child takes (3.17) */
    VESSEL_ANGLE,       /* alpha: angle between the two children, degrees (3.18) */
    VESSEL_GRAVI,       /* alpha_m: gravimorphism, degrees, > 0 bends toward the ground (3.19) */
    VESSEL_LEN_MAX,     /* M: upper bound of the relative length ratio (3.20) */
    VESSEL_LEN_MIN,     /* m: lower bound of the relative length ratio (3.21) */
    VESSEL_LEN_SCALE,   /* k_l: scale from relative to actual length (3.22) */
    VESSEL_LOCALS
} vessel_local;

typedef struct vessel_params {
    uint32_t vessels;         /* S, in [1, VESSEL_MAX_VESSELS] */
    double trunk_length;      /* l0^{0,0}, metres, (0, VESSEL_MAX_TRUNK_LENGTH] */
    double thickness;         /* k_d: d = k_d sqrt(S0), metres, [0, 1] */
    double gravicentralism;   /* k_c, [0, 1] */
    double phyllotaxis;       /* alpha_p, degrees, [0, 360] */
    double leaf_size;         /* l_l, metres, [0, VESSEL_MAX_LEAF_SIZE] */
    uint32_t leaf_density;    /* rho_l, leaves per terminal branch, [0, VESSEL_MAX_LEAF_DENSITY] */
    vessel_leaf_type leaf_type;
    leaf_affine_maps leaf;    /* t_leaf: the leaf's affine maps (`leaf:`) */
    uint32_t leaf_spray;      /* leaves fanned from the stalk on each quad, [1, VESSEL_MAX_LEAF_SPRAY] */
    int leaf_preset;          /* the leaf_affine_preset they are, or -1 for the scene's own maps */
    bark_fractal_params bark; /* t_bark: the fractal bark (`bark:`, `bark_angle:`) */
    bark_fractal_preset bark_preset; /* the preset it starts from */
    uint32_t sides;           /* n, [VESSEL_MIN_SIDES, VESSEL_MAX_SIDES] */
    vessel_polyline by_g[VESSEL_LOCALS]; /* the ^g polylines over g in [0, 15] */
    vessel_polyline by_w[VESSEL_LOCALS]; /* the ^w polylines over w in [0, 50] */
    double wind_sway;         /* w_s, undirected wind, [0, VESSEL_MAX_WIND] */
    double wind_strength;     /* w_g, directed wind, [0, VESSEL_MAX_WIND] */
    double wind_direction[3]; /* w, the way the directed wind blows (tree frame, Z up), not 0 */
    double flexibility;       /* k_f, [0, 1]; the sway is proportional to 1 - k_f (3.35) */
    double wind_time;         /* t of 3.35, radians: the frozen moment of the still */
    float bark_albedo[3];     /* linear RGB, [0, 1] */
    float leaf_albedo[3];     /* linear RGB; albedo + transmittance <= 1 per channel */
    float leaf_transmittance[3];
} vessel_params;

/* The per-order values at one (g, w) after the clamps of 3.17–3.22. */
typedef struct vessel_local_values {
    double split;   /* k_s^{g,w} in [1/2, 1] */
    double angle;   /* alpha^{g,w} in [0, 180] degrees */
    double gravi;   /* alpha_m^{g,w} in [-180, 180] degrees */
    double len_max; /* M^{g,w} */
    double len_min; /* m^{g,w} */
    double len_scale; /* k_l^{g,w} */
} vessel_local_values;

/* Every whole order the polylines span; orders past them read the last row or column. */
typedef struct vessel_order_table {
    vessel_local_values at[VESSEL_ORDER_G_MAX + 1][VESSEL_ORDER_W_MAX + 1];
} vessel_order_table;

/* The ranges of each polyline's values (004 §3.3, after 3.17–3.22) and its scene-file key. */
typedef struct vessel_polyline_rule {
    const char *key;
    double y_min, y_max;
} vessel_polyline_rule;
extern const vessel_polyline_rule vessel_rules_g[VESSEL_LOCALS];
extern const vessel_polyline_rule vessel_rules_w[VESSEL_LOCALS];

/* Checks every field against its range and the limits above, including the triangle count of
 * the full-grown tree. Returns 0, or SYLVA_ERR_PARAM (SYLVA_ERR_LIMIT for the triangle
 * count) with err set (param = the scene-file key) saying what is wrong and what would be
 * valid. */
int vessel_params_check(const vessel_params *p, plugin_err *err);

/* The clamped per-order values at Gravelius order g and Weibull order w (3.17–3.22), each
 * polyline read at min(g, 15) or min(w, 50). */
vessel_local_values vessel_local_at(const vessel_params *p, uint32_t g, uint32_t w);

/* Fills the table with vessel_local_at for every whole order. */
void vessel_order_table_fill(const vessel_params *p, vessel_order_table *t);

/* The table's values at any order (orders past the table read its last row or column). */
static inline const vessel_local_values *vessel_order_lookup(const vessel_order_table *t,
                                                             uint32_t g, uint32_t w)
{
    return &t->at[g > VESSEL_ORDER_G_MAX ? VESSEL_ORDER_G_MAX : g]
                 [w > VESSEL_ORDER_W_MAX ? VESSEL_ORDER_W_MAX : w];
}

#endif
