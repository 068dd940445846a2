/* vessel_config.c — the tree_vessel parameter schema (defaults: the beech preset of 004 §3.4.1)
 * and the preset-then-overrides reading of a scene block. A preset (vessel_presets.c) and a scene
 * block are read by the same code: a preset becomes a block that gives every key, its own value
 * or else the schema's default. */
#include "vessel_config.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "tree_look.h"
#include "vessel_presets.h"
#include "vessel_texture.h"

#define RANGE (SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX)
#define POSITIVE_RANGE (SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_MIN_EXCLUSIVE | SYLVA_PARAM_HAS_MAX)

static const char *const leaf_types[] = {"stacked", "staggered", "spiral", "bunched", "coniferous", NULL};

/* The beech preset's values, as the schema's defaults. */
static const double flat_w[] = {0, 1, 50, 1};
static const double beech_split_g[] = {0, 0.75, 15, 0.9};
static const double beech_angle_g[] = {0, 45, 15, 45};
static const double beech_gravi_g[] = {0, 0, 15, 0};
static const double beech_len_max_g[] = {0, 1, 15, 1};
static const double beech_len_min_g[] = {0, 1, 7.5, 0.45, 15, 1};
static const double beech_len_scale_g[] = {0, 1, 15, 1};
static const double beech_bark[] = {0.17, 0.165, 0.155};
static const double beech_leaf[] = {0.07, 0.14, 0.035};
static const double beech_leaf_t[] = {0.06, 0.14, 0.03};
static const double east[] = {1, 0, 0};

#define POLY(key, xs, lo, hi, u, text)                                                          \
    {.name = key, .type = SYLVA_P_POLYLINE, .flags = RANGE, .min = lo, .max = hi,              \
     .def_list = xs, .def_len = (uint32_t)(sizeof xs / sizeof xs[0] / 2), .min_len = 1,        \
     .max_len = VESSEL_POLYLINE_MAX_POINTS, .unit = u, .help = text}

const sylva_param_spec vessel_schema[VESSEL_SCHEMA_COUNT] = {
    {.name = "preset", .type = SYLVA_P_ENUM, .def_str = "beech", .choices = vessel_preset_names,
     .help = "Species the other keys start from: beech, spruce, weeping_willow (004) or maple "
             "(sylva's); every key given replaces the preset's value."},
    {.name = "vessels", .type = SYLVA_P_INT, .flags = RANGE, .def = 4000, .min = 1,
     .max = VESSEL_MAX_VESSELS,
     .help = "S: vessels in the trunk; the tree has S leaf-bearing branches and 2S - 1 segments."},
    {.name = "trunk_length", .type = SYLVA_P_REAL, .flags = POSITIVE_RANGE, .def = 5, .min = 0,
     .max = VESSEL_MAX_TRUNK_LENGTH, .unit = "m",
     .help = "l0: length of the first trunk segment, up to the first branching."},
    {.name = "thickness", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0.01, .min = 0, .max = 1,
     .unit = "m", .help = "k_d: a segment of S0 vessels is k_d sqrt(S0) thick."},
    {.name = "gravicentralism", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0.3, .min = 0,
     .max = 1, .help = "k_c: share of the main child's deviation turned back at each branching of the trunk (1: a straight trunk)."},
    {.name = "phyllotaxis", .type = SYLVA_P_REAL, .flags = RANGE, .def = 85, .min = 0, .max = 360,
     .unit = "deg", .help = "alpha_p: roll about the branch axis before each branching."},
    {.name = "leaf_size", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0.12, .min = 0,
     .max = VESSEL_MAX_LEAF_SIZE, .unit = "m", .help = "l_l: half-diagonal of each square leaf quad (its side is sqrt(2) l_l)."},
    {.name = "leaf_density", .type = SYLVA_P_INT, .flags = RANGE, .def = 16, .min = 0,
     .max = VESSEL_MAX_LEAF_DENSITY, .help = "rho_l: leaves on each terminal branch."},
    {.name = "leaf_type", .type = SYLVA_P_ENUM, .def_str = "spiral", .choices = leaf_types,
     .help = "How leaves sit on a terminal branch: stacked, staggered, spiral, bunched or coniferous."},
    {.name = "leaf", .type = SYLVA_P_STRING, .def_str = "beech",
     .help = "t_leaf, drawn by affine maps: a preset (beech, maple, spruce, shrub, willow) or maps "
             "\"a b c d e f[ p]; ...\" of the leaf quad's unit square."},
    {.name = "leaf_spray", .type = SYLVA_P_INT, .flags = RANGE, .def = 5, .min = 1, .max = VESSEL_MAX_LEAF_SPRAY,
     .help = "Leaves (or twigs) fanned from the stalk on each leaf quad's texture: 1 draws one leaf filling the quad."},
    {.name = "bark", .type = SYLVA_P_ENUM, .def_str = "smooth", .choices = tree_look_bark_names,
     .help = "t_bark, the fractal bark's preset: smooth, scaly, furrowed or fissured."},
    {.name = "bark_angle", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0, .min = -360, .max = 360,
     .unit = "deg", .help = "theta of the bark's lambda = e^(i theta); absent: the bark preset's own."},
    {.name = "bark_color", .type = SYLVA_P_VEC3, .flags = RANGE, .min = 0, .max = 1,
     .def_list = beech_bark, .def_len = 3, .help = "Linear RGB albedo of the bark."},
    {.name = "leaf_color", .type = SYLVA_P_VEC3, .flags = RANGE, .min = 0, .max = 1,
     .def_list = beech_leaf, .def_len = 3, .help = "Linear RGB reflectance of the leaves."},
    {.name = "leaf_transmittance", .type = SYLVA_P_VEC3, .flags = RANGE, .min = 0, .max = 1,
     .def_list = beech_leaf_t, .def_len = 3,
     .help = "Linear RGB transmittance of the leaves; with leaf_color at most 1 per channel."},
    {.name = "sides", .type = SYLVA_P_INT, .flags = RANGE, .def = 8, .min = VESSEL_MIN_SIDES,
     .max = VESSEL_MAX_SIDES, .help = "n: sides of each branch's truncated cone."},
    POLY("split_g", beech_split_g, 0.5, 1, NULL,
         "k_s^g: share of the vessels the main child takes, over Gravelius order 0..15."),
    POLY("split_w", flat_w, 0, 2, NULL, "k_s^w: factor on k_s^g over Weibull order 0..50."),
    POLY("angle_g", beech_angle_g, 0, 180, "deg",
         "alpha^g: angle between the two children, over Gravelius order 0..15."),
    POLY("angle_w", flat_w, 0, 2, NULL, "alpha^w: factor on alpha^g over Weibull order 0..50."),
    POLY("gravimorphism_g", beech_gravi_g, -180, 180, "deg",
         "alpha_m^g: bend toward the ground (negative: upward) at each branching, over Gravelius order 0..15."),
    POLY("gravimorphism_w", flat_w, 0, 2, NULL,
         "alpha_m^w: factor on alpha_m^g over Weibull order 0..50."),
    POLY("length_max_g", beech_len_max_g, 0, 10, NULL,
         "M^g: upper bound of a child's relative length ratio, over Gravelius order 0..15."),
    POLY("length_max_w", flat_w, 0, 2, NULL, "M^w: factor on M^g over Weibull order 0..50."),
    POLY("length_min_g", beech_len_min_g, 0, 10, NULL,
         "m^g: lower bound of a child's relative length ratio, over Gravelius order 0..15."),
    POLY("length_min_w", flat_w, 0, 2, NULL, "m^w: factor on m^g over Weibull order 0..50."),
    POLY("length_scale_g", beech_len_scale_g, 0, 10, NULL,
         "k_l^g: metres of actual length per unit of relative length, over Gravelius order 0..15."),
    POLY("length_scale_w", flat_w, 0, 2, NULL, "k_l^w: factor on k_l^g over Weibull order 0..50."),
    {.name = "wind_sway", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0, .min = 0,
     .max = VESSEL_MAX_WIND, .help = "w_s: strength of the undirected wind that sways each branch."},
    {.name = "wind_strength", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0, .min = 0,
     .max = VESSEL_MAX_WIND, .help = "w_g: strength of the directed wind; the trunk bends by w_g degrees."},
    {.name = "wind_direction", .type = SYLVA_P_VEC3, .def_list = east, .def_len = 3,
     .help = "w: the way the directed wind blows, in the tree's frame (Z up); not zero."},
    {.name = "flexibility", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0.5, .min = 0, .max = 1,
     .help = "k_f: the sway is proportional to 1 - k_f."},
    {.name = "wind_time", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0, .min = -VESSEL_MAX_WIND_TIME,
     .max = VESSEL_MAX_WIND_TIME, .unit = "rad", .help = "t: the frozen moment of the sway, the phase of sin(t + R)."},
};

static const sylva_value *given(const sylva_params *params, const char *key)
{
    const sylva_value *v = sylva_param(params, key);
    return v && v->is_set ? v : NULL;
}

static void read_real(const sylva_params *params, const char *key, double *dst)
{
    const sylva_value *v = given(params, key);
    if (v) *dst = v->r;
}

static void read_colour(const sylva_params *params, const char *key, float *dst)
{
    const sylva_value *v = given(params, key);
    if (v && v->list && v->len == 3)
        for (int k = 0; k < 3; k++) dst[k] = (float)v->list[k];
}

static int read_polyline(const sylva_params *params, const vessel_polyline_rule *rule,
                         double x_max, vessel_polyline *dst, plugin_err *err)
{
    const sylva_value *v = given(params, rule->key);
    if (!v) return 0;
    return vessel_polyline_set(dst, v->list, v->len, x_max, rule->y_min, rule->y_max, rule->key,
                               err);
}

/* Copies the keys `params` gives onto *out. Returns 0, or -1 with err set. */
static int read_given(const sylva_params *params, vessel_params *out, plugin_err *err)
{
    const sylva_value *v;
    if ((v = given(params, "vessels"))) {
        if (v->i < 1 || v->i > VESSEL_MAX_VESSELS)
            return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "vessels", "'vessels' (S) is %lld; a tree needs 1 to %u "
                               "vessels in its trunk", (long long)v->i, VESSEL_MAX_VESSELS);
        out->vessels = (uint32_t)v->i;
    }
    read_real(params, "trunk_length", &out->trunk_length);
    read_real(params, "thickness", &out->thickness);
    read_real(params, "gravicentralism", &out->gravicentralism);
    read_real(params, "phyllotaxis", &out->phyllotaxis);
    read_real(params, "leaf_size", &out->leaf_size);
    if ((v = given(params, "leaf_density"))) {
        if (v->i < 0 || v->i > VESSEL_MAX_LEAF_DENSITY)
            return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "leaf_density", "'leaf_density' is %lld; valid values are 0 "
                               "to %u leaves per branch", (long long)v->i, VESSEL_MAX_LEAF_DENSITY);
        out->leaf_density = (uint32_t)v->i;
    }
    if ((v = given(params, "leaf_type"))) out->leaf_type = (vessel_leaf_type)v->i;
    if ((v = given(params, "leaf_spray"))) out->leaf_spray = (uint32_t)v->i;
    char why[PLUGIN_ERR_MAX - 64];
    if ((v = given(params, "leaf"))) {
        int named = tree_look_leaf(v->s, VESSEL_LEAF_TEXTURE_SIZE, &out->leaf, why, sizeof why);
        if (named < 0) return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "leaf", "'leaf': %s", why);
        out->leaf_preset = named == TREE_LOOK_USER_MAPS ? -1 : named;
    }
    /* a bark preset brings its own angle unless bark_angle is given too */
    const sylva_value *bark = given(params, "bark"), *angle = given(params, "bark_angle");
    if (bark) out->bark_preset = (bark_fractal_preset)bark->i;
    if ((bark || angle) &&
        tree_look_bark((int)out->bark_preset, angle ? angle->r : NAN, &out->bark, why, sizeof why))
        return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, angle ? "bark_angle" : "bark", "'%s': %s",
                           angle ? "bark_angle" : "bark", why);
    read_colour(params, "bark_color", out->bark_albedo);
    read_colour(params, "leaf_color", out->leaf_albedo);
    read_colour(params, "leaf_transmittance", out->leaf_transmittance);
    if ((v = given(params, "sides"))) {
        if (v->i < VESSEL_MIN_SIDES || v->i > VESSEL_MAX_SIDES)
            return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "sides", "'sides' is %lld; branch cones have %u to %u sides",
                               (long long)v->i, VESSEL_MIN_SIDES, VESSEL_MAX_SIDES);
        out->sides = (uint32_t)v->i;
    }
    for (int k = 0; k < VESSEL_LOCALS; k++)
        if (read_polyline(params, &vessel_rules_g[k], VESSEL_ORDER_G_MAX, &out->by_g[k], err) ||
            read_polyline(params, &vessel_rules_w[k], VESSEL_ORDER_W_MAX, &out->by_w[k], err))
            return -1;
    read_real(params, "wind_sway", &out->wind_sway);
    read_real(params, "wind_strength", &out->wind_strength);
    if ((v = given(params, "wind_direction")) && v->list && v->len == 3)
        for (int k = 0; k < 3; k++) out->wind_direction[k] = v->list[k];
    read_real(params, "flexibility", &out->flexibility);
    read_real(params, "wind_time", &out->wind_time);
    return 0;
}

static int64_t choice_index(const sylva_param_spec *spec, const char *s)
{
    for (int64_t k = 0; s && spec->choices && spec->choices[k]; k++)
        if (!strcmp(spec->choices[k], s)) return k;
    return -1;
}

int vessel_preset_get(vessel_preset which, vessel_params *out)
{
    if ((unsigned)which >= VESSEL_PRESETS) return -1;
    const sylva_preset *preset = &vessel_presets[which];
    sylva_value values[VESSEL_SCHEMA_COUNT];
    for (uint32_t k = 0; k < VESSEL_SCHEMA_COUNT; k++) {
        const sylva_param_spec *spec = &vessel_schema[k];
        sylva_value v = {.is_set = 1, .r = spec->def, .i = (int64_t)spec->def, .s = spec->def_str,
                         .list = spec->def_list, .len = spec->def_len};
        for (uint32_t j = 0; j < preset->n_values; j++) {
            const sylva_preset_value *pv = &preset->values[j];
            if (strcmp(pv->param, spec->name)) continue;
            v = (sylva_value){.is_set = 1, .r = pv->r, .i = (int64_t)pv->r, .s = pv->s,
                              .list = pv->list, .len = pv->len};
        }
        if (spec->type == SYLVA_P_ENUM) v.i = choice_index(spec, v.s);
        if (!strcmp(spec->name, "bark_angle")) v.is_set = 0; /* a preset's bark keeps its own angle */
        values[k] = v;
    }
    values[0].i = which; /* the preset key itself */
    sylva_params block = {.spec = vessel_schema, .n = VESSEL_SCHEMA_COUNT, .values = values};
    plugin_err err = {0};
    memset(out, 0, sizeof *out);
    return read_given(&block, out, &err) ? -1 : 0;
}

int vessel_config_read(const sylva_params *params, vessel_params *out, plugin_err *err)
{
    const sylva_value *preset = sylva_param(params, "preset");
    if (!preset || vessel_preset_get((vessel_preset)preset->i, out))
        return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "preset", "unknown preset; the presets are beech, spruce, "
                           "weeping_willow and maple");
    if (read_given(params, out, err)) return -1;
    return vessel_params_check(out, err);
}
