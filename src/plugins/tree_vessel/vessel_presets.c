/* vessel_presets.c — preset parameter sets. Beech, spruce and weeping willow carry 004 §3.4's
 * values exactly (decimal commas read as points; polylines as (order, value) points); maple is
 * sylva's. */
#include "vessel_presets.h"

#include <string.h>

const char *const vessel_preset_names[VESSEL_PRESETS + 1] = {"beech", "spruce", "weeping_willow",
                                                             "maple", NULL};

#define PL(...) ((const double[]){__VA_ARGS__}), (uint32_t)(sizeof((const double[]){__VA_ARGS__}) / (2 * sizeof(double)))

static void line(vessel_polyline *p, const double *xy, uint32_t n)
{
    p->n = n;
    for (uint32_t i = 0; i < n; i++) p->x[i] = xy[2 * i], p->y[i] = xy[2 * i + 1];
}

static void set3(float *dst, float a, float b, float c) { dst[0] = a, dst[1] = b, dst[2] = c; }

/* Everything a preset does not state: flat polylines of value 1 for the w side, no wind. */
static void base(vessel_params *p)
{
    memset(p, 0, sizeof *p);
    for (int k = 0; k < VESSEL_LOCALS; k++) line(&p->by_w[k], PL(0, 1, 50, 1));
    p->sides = 8;
    p->wind_direction[0] = 1.0;
    p->flexibility = 0.5;
}

static void beech(vessel_params *p)
{
    base(p);
    p->vessels = 1000, p->trunk_length = 5, p->thickness = 0.01, p->phyllotaxis = 85;
    p->gravicentralism = 0.3, p->leaf_size = 0.1, p->leaf_density = 5;
    p->leaf_type = VESSEL_LEAF_SPIRAL;
    line(&p->by_g[VESSEL_SPLIT], PL(0, 0.75, 15, 0.9));
    line(&p->by_g[VESSEL_ANGLE], PL(0, 45, 15, 45));
    line(&p->by_g[VESSEL_LEN_MIN], PL(0, 1, 7.5, 0.45, 15, 1));
    line(&p->by_g[VESSEL_LEN_MAX], PL(0, 1, 15, 1));
    line(&p->by_g[VESSEL_LEN_SCALE], PL(0, 1, 15, 1));
    line(&p->by_g[VESSEL_GRAVI], PL(0, 0, 15, 0));
    p->leaf_shape = VESSEL_LEAF_SHAPE_OVATE, p->bark = VESSEL_BARK_SMOOTH;
    set3(p->bark_albedo, 0.17f, 0.165f, 0.155f);
    set3(p->leaf_albedo, 0.07f, 0.14f, 0.035f);
    set3(p->leaf_transmittance, 0.06f, 0.14f, 0.03f);
}

static void spruce(vessel_params *p)
{
    base(p);
    p->vessels = 6000, p->trunk_length = 5.47, p->thickness = 0.005, p->phyllotaxis = 85;
    p->gravicentralism = 0.98, p->leaf_size = 0.1815, p->leaf_density = 30;
    p->leaf_type = VESSEL_LEAF_STACKED;
    line(&p->by_g[VESSEL_SPLIT],
         PL(0, 0.955, 0.7749, 0.9615, 1.827, 0.8288, 4.207, 0.8269, 15, 0.8294));
    line(&p->by_w[VESSEL_SPLIT], PL(0, 1, 42.89, 1.005, 42.89, 0.654, 50, 0.6256));
    line(&p->by_g[VESSEL_ANGLE], PL(0, 128.8, 1.164, 17.91, 3.621, 45.21, 15, 35.83));
    line(&p->by_g[VESSEL_LEN_MIN], PL(0, 0.7109, 1.293, 0.8531, 15, 1));
    line(&p->by_g[VESSEL_LEN_MAX], PL(0, 0.9953, 15, 1));
    line(&p->by_g[VESSEL_LEN_SCALE], PL(0, 0.7109, 0.7749, 0.5385, 2.522, 1.327, 15, 1));
    line(&p->by_w[VESSEL_LEN_SCALE], PL(0, 1.014, 38.58, 1.014, 45.26, 0.5877, 50, 0.01896));
    line(&p->by_g[VESSEL_GRAVI],
         PL(0, 0, 0.3875, 34.62, 1.034, -4.265, 1.55, -4.154, 2.974, -5.972, 15, -0.8532));
    p->sides = 6;
    p->leaf_shape = VESSEL_LEAF_SHAPE_NEEDLES, p->bark = VESSEL_BARK_SCALY;
    set3(p->bark_albedo, 0.17f, 0.11f, 0.08f);
    set3(p->leaf_albedo, 0.030f, 0.065f, 0.030f);
    set3(p->leaf_transmittance, 0.010f, 0.035f, 0.010f);
}

static void weeping_willow(vessel_params *p)
{
    base(p);
    p->vessels = 1500, p->trunk_length = 1, p->thickness = 0.01, p->phyllotaxis = 85;
    p->gravicentralism = 0.2, p->leaf_size = 0.3452, p->leaf_density = 5;
    p->leaf_type = VESSEL_LEAF_CONIFEROUS;
    line(&p->by_g[VESSEL_SPLIT], PL(0, 0.8507, 3.75, 0.7749, 15, 0.9));
    line(&p->by_g[VESSEL_ANGLE], PL(0, 17.91, 1.875, 57.16, 15, 45));
    line(&p->by_g[VESSEL_LEN_MIN], PL(0, 1, 1.81, 0.9953, 15, 1));
    line(&p->by_w[VESSEL_LEN_MIN], PL(0, 0.9668, 50, 1));
    line(&p->by_g[VESSEL_LEN_MAX], PL(0, 0.9953, 1.422, 1.848, 15, 1));
    line(&p->by_g[VESSEL_LEN_SCALE], PL(0, 1, 15, 1));
    line(&p->by_w[VESSEL_LEN_SCALE], PL(0, 1, 22.63, 0.9953, 37.07, 0.7678, 50, 1));
    line(&p->by_g[VESSEL_GRAVI], PL(0, 84.45, 1.746, 94.69, 15, 110));
    line(&p->by_w[VESSEL_GRAVI], PL(0, 0.6446, 50, 1));
    p->leaf_shape = VESSEL_LEAF_SHAPE_LANCEOLATE, p->bark = VESSEL_BARK_FURROWED;
    set3(p->bark_albedo, 0.20f, 0.17f, 0.13f);
    set3(p->leaf_albedo, 0.11f, 0.17f, 0.05f);
    set3(p->leaf_transmittance, 0.10f, 0.17f, 0.04f);
}

/* sylva's maple (not in 004): a shorter bole than the beech, a broad dome, opposite leaves
 * (pairs, phyllotaxis 90 degrees), larger lobed leaves, main limbs a little upright and the
 * outer shoots a little drooping. */
static void maple(vessel_params *p)
{
    base(p);
    p->vessels = 2000, p->trunk_length = 4, p->thickness = 0.011, p->phyllotaxis = 90;
    p->gravicentralism = 0.5, p->leaf_size = 0.13, p->leaf_density = 8;
    p->leaf_type = VESSEL_LEAF_STACKED;
    line(&p->by_g[VESSEL_SPLIT], PL(0, 0.6, 3, 0.72, 15, 0.85));
    line(&p->by_g[VESSEL_ANGLE], PL(0, 40, 3, 45, 15, 40));
    line(&p->by_g[VESSEL_LEN_MIN], PL(0, 1, 5, 0.75, 15, 0.85));
    line(&p->by_g[VESSEL_LEN_MAX], PL(0, 1, 15, 1));
    line(&p->by_g[VESSEL_LEN_SCALE], PL(0, 1, 15, 0.9));
    line(&p->by_g[VESSEL_GRAVI], PL(0, 0, 1, 2, 15, 6));
    p->leaf_shape = VESSEL_LEAF_SHAPE_PALMATE, p->bark = VESSEL_BARK_FISSURED;
    set3(p->bark_albedo, 0.20f, 0.18f, 0.15f);
    set3(p->leaf_albedo, 0.08f, 0.15f, 0.035f);
    set3(p->leaf_transmittance, 0.08f, 0.16f, 0.03f);
}

int vessel_preset_get(vessel_preset which, vessel_params *out)
{
    switch (which) {
    case VESSEL_PRESET_BEECH: beech(out); return 0;
    case VESSEL_PRESET_SPRUCE: spruce(out); return 0;
    case VESSEL_PRESET_WEEPING_WILLOW: weeping_willow(out); return 0;
    case VESSEL_PRESET_MAPLE: maple(out); return 0;
    default: return -1;
    }
}
