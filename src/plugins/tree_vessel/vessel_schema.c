/* vessel_schema.c — the tree_vessel parameter schema: static const data and nothing else. Its
 * defaults are the beech preset of 004 §3.4.1, so `sylva plugins --describe tree_vessel` shows a
 * complete species. */
#include "vessel_schema.h"

#include "tree_look.h"
#include "vessel_params.h"
#include "vessel_polyline.h"
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
