/* vessel_params.c — the checks of a vessel parameter set and the per-order values with the
 * clamps of 004 (3.17)–(3.22). */
#include "vessel_params.h"

#include <math.h>

/* Value ranges of the auxiliary parameters as 004 §3.3 states them beside 3.17–3.22. */
const vessel_polyline_rule vessel_rules_g[VESSEL_LOCALS] = {
    [VESSEL_SPLIT] = {"split_g", 0.5, 1.0},
    [VESSEL_ANGLE] = {"angle_g", 0.0, 180.0},
    [VESSEL_GRAVI] = {"gravimorphism_g", -180.0, 180.0},
    [VESSEL_LEN_MAX] = {"length_max_g", 0.0, 10.0},
    [VESSEL_LEN_MIN] = {"length_min_g", 0.0, 10.0},
    [VESSEL_LEN_SCALE] = {"length_scale_g", 0.0, 10.0},
};
const vessel_polyline_rule vessel_rules_w[VESSEL_LOCALS] = {
    [VESSEL_SPLIT] = {"split_w", 0.0, 2.0},
    [VESSEL_ANGLE] = {"angle_w", 0.0, 2.0},
    [VESSEL_GRAVI] = {"gravimorphism_w", 0.0, 2.0},
    [VESSEL_LEN_MAX] = {"length_max_w", 0.0, 2.0},
    [VESSEL_LEN_MIN] = {"length_min_w", 0.0, 2.0},
    [VESSEL_LEN_SCALE] = {"length_scale_w", 0.0, 2.0},
};

static int check_real(double v, double lo, double hi, int lo_open, const char *key,
                      const char *unit, plugin_err *err)
{
    if (isfinite(v) && (lo_open ? v > lo : v >= lo) && v <= hi) return 0;
    return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, key, "'%s' is %g%s; valid values are %s%g to %g%s", key, v, unit,
                       lo_open ? "above " : "", lo, hi, unit);
}

static int check_polyline(const vessel_polyline *p, double x_max, const vessel_polyline_rule *r,
                          plugin_err *err)
{
    double xy[2 * VESSEL_POLYLINE_MAX_POINTS];
    if (p->n > VESSEL_POLYLINE_MAX_POINTS)
        return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, r->key, "'%s' has %u points; at most %u are allowed", r->key, p->n,
                           VESSEL_POLYLINE_MAX_POINTS);
    for (uint32_t i = 0; i < p->n; i++) xy[2 * i] = p->x[i], xy[2 * i + 1] = p->y[i];
    vessel_polyline scratch;
    return vessel_polyline_set(&scratch, xy, p->n, x_max, r->y_min, r->y_max, r->key, err);
}

int vessel_params_check(const vessel_params *p, plugin_err *err)
{
    if (p->vessels < 1 || p->vessels > VESSEL_MAX_VESSELS)
        return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "vessels",
                           "'vessels' (S) is %u; a tree needs 1 to %u vessels in its trunk",
                           p->vessels, VESSEL_MAX_VESSELS);
    if (check_real(p->trunk_length, 0.0, VESSEL_MAX_TRUNK_LENGTH, 1, "trunk_length", " m", err) ||
        check_real(p->thickness, 0.0, 1.0, 0, "thickness", "", err) ||
        check_real(p->gravicentralism, 0.0, 1.0, 0, "gravicentralism", "", err) ||
        check_real(p->phyllotaxis, 0.0, 360.0, 0, "phyllotaxis", " deg", err) ||
        check_real(p->leaf_size, 0.0, VESSEL_MAX_LEAF_SIZE, 0, "leaf_size", " m", err) ||
        check_real(p->wind_sway, 0.0, VESSEL_MAX_WIND, 0, "wind_sway", "", err) ||
        check_real(p->wind_strength, 0.0, VESSEL_MAX_WIND, 0, "wind_strength", "", err) ||
        check_real(p->flexibility, 0.0, 1.0, 0, "flexibility", "", err) ||
        check_real(p->wind_time, -VESSEL_MAX_WIND_TIME, VESSEL_MAX_WIND_TIME, 0, "wind_time", " rad", err))
        return -1;
    if (p->leaf_spray < 1 || p->leaf_spray > VESSEL_MAX_LEAF_SPRAY)
        return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "leaf_spray", "'leaf_spray' is %u; a quad carries 1 to %u leaves",
                           p->leaf_spray, VESSEL_MAX_LEAF_SPRAY);
    if (p->leaf_density > VESSEL_MAX_LEAF_DENSITY)
        return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "leaf_density",
                           "'leaf_density' is %u leaves per branch; valid values are 0 to %u",
                           p->leaf_density, VESSEL_MAX_LEAF_DENSITY);
    if ((unsigned)p->leaf_type >= VESSEL_LEAF_TYPES)
        return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "leaf_type", "'leaf_type' %d is not one of the five distributions",
                           (int)p->leaf_type);
    char why[256];
    if (leaf_affine_check(&p->leaf, why, sizeof why))
        return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "leaf", "'leaf': %s", why);
    if ((unsigned)p->bark_preset >= BARK_FRACTAL_PRESETS)
        return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "bark", "'bark': not a preset");
    if (bark_fractal_check(&p->bark, why, sizeof why))
        return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "bark", "'bark': %s", why);
    if (p->sides < VESSEL_MIN_SIDES || p->sides > VESSEL_MAX_SIDES)
        return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "sides", "'sides' is %u; branch cones have %u to %u sides",
                           p->sides, VESSEL_MIN_SIDES, VESSEL_MAX_SIDES);
    double wd = 0;
    for (int k = 0; k < 3; k++) {
        if (!isfinite(p->wind_direction[k]))
            return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "wind_direction", "'wind_direction' must be finite");
        wd += p->wind_direction[k] * p->wind_direction[k];
    }
    if (!(wd > 0))
        return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "wind_direction",
                           "'wind_direction' is the zero vector; give the way the wind blows, "
                           "e.g. [1, 0, 0] for toward the east");
    for (int k = 0; k < 3; k++) {
        if (!(p->bark_albedo[k] >= 0 && p->bark_albedo[k] <= 1))
            return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "bark_color", "'bark_color' channels must be in [0, 1]");
        if (!(p->leaf_albedo[k] >= 0 && p->leaf_albedo[k] <= 1))
            return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "leaf_color", "'leaf_color' channels must be in [0, 1]");
        if (!(p->leaf_transmittance[k] >= 0 && p->leaf_albedo[k] + p->leaf_transmittance[k] <= 1))
            return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "leaf_transmittance",
                               "'leaf_transmittance' channel %d is %g with leaf_color %g; a leaf "
                               "cannot scatter more than it receives (their sum is at most 1)",
                               k, p->leaf_transmittance[k], p->leaf_albedo[k]);
    }
    for (int k = 0; k < VESSEL_LOCALS; k++)
        if (check_polyline(&p->by_g[k], VESSEL_ORDER_G_MAX, &vessel_rules_g[k], err) ||
            check_polyline(&p->by_w[k], VESSEL_ORDER_W_MAX, &vessel_rules_w[k], err))
            return -1;
    /* The full-grown tree is the largest variant: S - 1 truncated cones of 2n triangles, S cones
     * of n, and 2 rho_l triangles of leaves on each of the S terminal branches. */
    uint64_t S = p->vessels, bark = (S - 1) * 2 * p->sides + S * p->sides;
    uint64_t leaves = S * 2 * p->leaf_density;
    if (bark + leaves > VESSEL_MAX_TRIANGLES)
        return plugin_fail_key(err, SYLVA_ERR_LIMIT, NULL, leaves > bark ? "leaf_density" : "vessels",
                           "this tree would need %llu triangles (%llu bark, %llu leaves); one "
                           "model may have at most %u: lower vessels (S), leaf_density or sides",
                           (unsigned long long)(bark + leaves), (unsigned long long)bark,
                           (unsigned long long)leaves, VESSEL_MAX_TRIANGLES);
    return 0;
}

static double clamp(double v, double lo, double hi) { return v < lo ? lo : v > hi ? hi : v; }

vessel_local_values vessel_local_at(const vessel_params *p, uint32_t g, uint32_t w)
{
    double gx = g > VESSEL_ORDER_G_MAX ? VESSEL_ORDER_G_MAX : g;
    double wx = w > VESSEL_ORDER_W_MAX ? VESSEL_ORDER_W_MAX : w;
    double v[VESSEL_LOCALS];
    for (int k = 0; k < VESSEL_LOCALS; k++)
        v[k] = vessel_polyline_at(&p->by_g[k], gx) * vessel_polyline_at(&p->by_w[k], wx);
    vessel_local_values r;
    r.split = fmax(fmin(v[VESSEL_SPLIT], 1.0), 0.5);     /* (3.17) */
    r.angle = fmin(v[VESSEL_ANGLE], 180.0);              /* (3.18) */
    r.gravi = clamp(v[VESSEL_GRAVI], -180.0, 180.0);     /* (3.19) */
    r.len_max = v[VESSEL_LEN_MAX];                       /* (3.20) */
    r.len_min = v[VESSEL_LEN_MIN];                       /* (3.21) */
    r.len_scale = v[VESSEL_LEN_SCALE];                   /* (3.22) */
    return r;
}

void vessel_order_table_fill(const vessel_params *p, vessel_order_table *t)
{
    for (uint32_t g = 0; g <= VESSEL_ORDER_G_MAX; g++)
        for (uint32_t w = 0; w <= VESSEL_ORDER_W_MAX; w++) t->at[g][w] = vessel_local_at(p, g, w);
}
