/* wp_schema.c — the tree_weber_penn parameter schema: static const data and nothing else. The
 * `model` members carry wp_param_table's defaults and ranges (Arbaro 1.9's), one member per row
 * Arbaro's growth reads; test plugin.tree_weber_penn.config.schema_follows_the_table holds them
 * to the table. `sylva plugins --describe tree_weber_penn` prints it. */
#include "wp_schema.h"

#include "tree_look.h"

#define MIN (SYLVA_PARAM_HAS_MIN)
#define RANGE (SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX)
#define INT_LO (-2147483648.0)
#define INT_HI 2147483647.0

/* A general parameter: INT or REAL with the table's default, flags and bounds. */
#define GEN(key, ty, d, fl, lo, hi, u, text) \
    {.name = key, .type = SYLVA_P_##ty, .flags = fl, .def = d, .min = lo, .max = hi, .unit = u, .help = text}
/* A per-level parameter: a list of 1 to 4 numbers, levels 0 (trunk) to 3, defaults `d`. */
#define LVL(key, d, fl, lo, hi, u, text)                                                                    \
    {.name = key, .type = SYLVA_P_LIST, .flags = fl, .min = lo, .max = hi, .def_list = d, .def_len = 4,     \
     .min_len = 1, .max_len = 4, .unit = u, .help = text}

static const double d_length[] = {1, 0.5, 0.5, 0.5};
static const double d_zero[] = {0, 0, 0, 0};
static const double d_taper[] = {1, 1, 1, 1};
static const double d_curve_res[] = {3, 3, 1, 1};
static const double d_down_angle[] = {0, 30, 30, 30};
static const double d_rotate[] = {0, 120, 120, 120};
static const double d_branches[] = {1, 10, 5, 5};
static const double d_branch_dist[] = {0, 1, 1, 1};

const sylva_param_spec wp_model_schema[WP_MODEL_SCHEMA_COUNT] = {
    GEN("shape", INT, 0, RANGE, 0, 8, NULL,
        "Shape: tree shape: 0 conical, 1 spherical, 2 hemispherical, 3 cylindrical, 4 tapered cylindrical, "
        "5 flame, 6 inverse conical, 7 tend flame, 8 envelope."),
    GEN("levels", INT, 3, RANGE, 0, 9, NULL,
        "Levels: levels of recursion (stem levels; the last bears leaves), of the full-grown tree."),
    GEN("scale", REAL, 10, MIN, 1e-6, 0, "m", "Scale: average tree size in metres (of the full-grown tree)."),
    GEN("scale_v", REAL, 0, MIN, 0, 0, "m", "ScaleV: variation of tree size in metres."),
    GEN("base_size", REAL, 0.25, RANGE, 0, 1, NULL, "BaseSize: fraction of the trunk without branches."),
    GEN("base_splits", INT, 0, RANGE, 0, INT_HI, NULL, "0BaseSplits: clones made at the trunk's base."),
    GEN("ratio", REAL, 0.05, MIN, 1e-6, 0, NULL, "Ratio: trunk radius to trunk length."),
    GEN("ratio_power", REAL, 1, 0, 0, 0, NULL, "RatioPower: how child radii fall with level."),
    GEN("flare", REAL, 0.5, MIN, -1, 0, NULL, "Flare: widening of the trunk's base."),
    GEN("lobes", INT, 0, RANGE, 0, INT_HI, NULL, "Lobes: lobes of the trunk's cross section."),
    GEN("lobe_depth", REAL, 0, MIN, 0, 0, NULL, "LobeDepth: depth of the lobes."),
    GEN("leaves", INT, 0, RANGE, INT_LO, INT_HI, NULL,
        "Leaves: leaves per stem of the last level (negative: fans)."),
    {.name = "leaf_shape", .type = SYLVA_P_STRING, .def_str = "0",
     .help = "LeafShape: leaf shape id or name, drawn when leaf is own (and giving the size of a leaf card)."},
    GEN("leaf_scale", REAL, 0.2, MIN, 1e-6, 0, "m", "LeafScale: leaf length in metres."),
    GEN("leaf_scale_x", REAL, 0.5, MIN, 1e-6, 0, NULL, "LeafScaleX: leaf width to length."),
    GEN("leaf_bend", REAL, 0.3, RANGE, 0, 1, NULL, "LeafBend: how far leaves turn to the light."),
    GEN("leaf_stem_len", REAL, 0.5, 0, 0, 0, NULL, "LeafStemLen: leaf stalk length to leaf length."),
    GEN("leaf_distrib", INT, 4, RANGE, 0, 8, NULL,
        "LeafDistrib: shape id of the leaves' distribution along a stem."),
    GEN("leaf_quality", REAL, 1, RANGE, 1e-6, 1, NULL, "LeafQuality: leaf count reduction."),
    GEN("smooth", REAL, 0.5, RANGE, 0, 1, NULL, "Smooth: mesh smoothness."),
    GEN("attraction_up", REAL, 0, 0, 0, 0, NULL, "AttractionUp: upward pull on stems."),
    GEN("prune_ratio", REAL, 0, RANGE, 0, 1, NULL, "PruneRatio: how much of the envelope pruning acts."),
    GEN("prune_width", REAL, 0.5, RANGE, 0, 1, NULL, "PruneWidth: width of the envelope to its height."),
    GEN("prune_width_peak", REAL, 0.5, RANGE, 0, 1, NULL,
        "PruneWidthPeak: height of the envelope's widest point."),
    GEN("prune_power_low", REAL, 0.5, MIN, 0, 0, NULL,
        "PrunePowerLow: curvature of the envelope below its peak."),
    GEN("prune_power_high", REAL, 0.5, MIN, 0, 0, NULL,
        "PrunePowerHigh: curvature of the envelope above its peak."),
    GEN("trunk_scale", REAL, 1, MIN, 1e-6, 0, NULL, "0Scale: trunk radius scale."),
    GEN("trunk_scale_v", REAL, 0, MIN, 0, 0, NULL, "0ScaleV: variation of 0Scale."),
    LVL("length", d_length, MIN, 0, 0, NULL,
        "nLength per level: stem length to parent (level 0: to Scale); at least 1e-07 at a level the tree grows."),
    LVL("length_v", d_zero, MIN, 0, 0, NULL, "nLengthV per level: variation of nLength."),
    LVL("taper", d_taper, RANGE, 0, 2.99999999, NULL,
        "nTaper per level: radius taper: 0-1 cone, 1-2 spherical, 2-3 periodic."),
    LVL("seg_splits", d_zero, MIN, 0, 0, NULL, "nSegSplits per level: clones per segment."),
    LVL("split_angle", d_zero, RANGE, 0, 180, "deg", "nSplitAngle per level: angle between clones in degrees."),
    LVL("split_angle_v", d_zero, RANGE, 0, 180, "deg", "nSplitAngleV per level: variation of nSplitAngle."),
    LVL("curve_res", d_curve_res, RANGE, 0, INT_HI, NULL,
        "nCurveRes per level: segments per stem; whole numbers, at least 1 at a level the tree grows."),
    LVL("curve", d_zero, 0, 0, 0, "deg", "nCurve per level: stem curvature in degrees."),
    LVL("curve_back", d_zero, 0, 0, 0, "deg", "nCurveBack per level: curvature of the stem's upper half."),
    LVL("curve_v", d_zero, MIN, -90, 0, "deg", "nCurveV per level: variation of nCurve (negative: helix)."),
    LVL("down_angle", d_down_angle, RANGE, -179.9999999, 179.999999, "deg",
        "nDownAngle per level: angle from the parent stem in degrees."),
    LVL("down_angle_v", d_zero, RANGE, -179.9999999, 179.9999999, "deg",
        "nDownAngleV per level: variation of nDownAngle (negative: by position)."),
    LVL("rotate", d_rotate, RANGE, -360, 360, "deg", "nRotate per level: angle about the parent to the previous child."),
    LVL("rotate_v", d_zero, RANGE, -360, 360, "deg", "nRotateV per level: variation of nRotate."),
    LVL("branches", d_branches, RANGE, 0, INT_HI, NULL, "nBranches per level: child stems per stem; whole numbers."),
    LVL("branch_dist", d_branch_dist, RANGE, 0, 1, NULL,
        "nBranchDist per level: distribution of whorls along a stem."),
};

const char *const wp_model_arbaro[WP_MODEL_SCHEMA_COUNT] = {
    "Shape", "Levels", "Scale", "ScaleV", "BaseSize", "0BaseSplits", "Ratio", "RatioPower", "Flare", "Lobes",
    "LobeDepth", "Leaves", "LeafShape", "LeafScale", "LeafScaleX", "LeafBend", "LeafStemLen", "LeafDistrib",
    "LeafQuality", "Smooth", "AttractionUp", "PruneRatio", "PruneWidth", "PruneWidthPeak", "PrunePowerLow",
    "PrunePowerHigh", "0Scale", "0ScaleV", "nLength", "nLengthV", "nTaper", "nSegSplits", "nSplitAngle",
    "nSplitAngleV", "nCurveRes", "nCurve", "nCurveBack", "nCurveV", "nDownAngle", "nDownAngleV", "nRotate",
    "nRotateV", "nBranches", "nBranchDist",
};

static const double def_leaf_color[] = {0.07, 0.16, 0.035};
static const double def_leaf_transmittance[] = {0.05, 0.13, 0.02};
static const double def_bark_color[] = {0.13, 0.10, 0.08};

const sylva_param_spec wp_schema[WP_SCHEMA_COUNT] = {
    {.name = "file", .type = SYLVA_P_PATH,
     .help = "An Arbaro species file (<arbaro><species ...>) or Helios' WeberPennTreeLibrary.xml, relative to "
             "the scene file; give file, model or both."},
    {.name = "name", .type = SYLVA_P_STRING,
     .help = "Which species of file (Arbaro's species name, Helios' label); needed when the file holds more "
             "than one."},
    {.name = "seed", .type = SYLVA_P_INT, .flags = RANGE, .def = 13, .min = INT_LO, .max = INT_HI,
     .help = "Arbaro's seed of the full-grown variant (13 is Arbaro's own tree); each younger variant takes "
             "the next seed up."},
    {.name = "model", .type = SYLVA_P_GROUP, .group = wp_model_schema, .n_group = WP_MODEL_SCHEMA_COUNT,
     .help = "The Weber-Penn parameters, each replacing the file's value (without file, the species itself; "
             "a parameter not given keeps Arbaro's default)."},
    {.name = "leaf", .type = SYLVA_P_STRING, .def_str = "own",
     .help = "own: the species' LeafShape as Arbaro draws it; or a card of that leaf's proportions "
             "whose leaf has that leaf's area, with the affine-map leaf texture of a preset (beech, maple, spruce, shrub, willow) or of maps "
             "\"a b c d e f[ p]; ...\"."},
    {.name = "leaf_color", .type = SYLVA_P_VEC3, .flags = RANGE, .min = 0, .max = 1, .def_list = def_leaf_color,
     .def_len = 3, .help = "Linear RGB reflectance of the leaves (multiplied by a leaf texture's veins)."},
    {.name = "leaf_transmittance", .type = SYLVA_P_VEC3, .flags = RANGE, .min = 0, .max = 1,
     .def_list = def_leaf_transmittance, .def_len = 3,
     .help = "Linear RGB diffuse transmittance of the leaves; plus leaf_color at most 1 per channel."},
    {.name = "bark_color", .type = SYLVA_P_VEC3, .flags = RANGE, .min = 0, .max = 1, .def_list = def_bark_color,
     .def_len = 3, .help = "Linear RGB reflectance of the bark (multiplied by the bark texture)."},
    {.name = "bark", .type = SYLVA_P_ENUM, .def_str = "smooth", .choices = tree_look_bark_names,
     .help = "The fractal bark's preset: smooth, scaly, furrowed or fissured."},
    {.name = "bark_angle", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0, .min = -360, .max = 360, .unit = "deg",
     .help = "theta of the bark's lambda = e^(i theta); absent: the preset's own."},
};
