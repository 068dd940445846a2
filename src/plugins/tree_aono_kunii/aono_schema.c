/* aono_schema.c — the parameter schema of tree_aono_kunii: every parameter of seed 000
 * §3.1–3.3 (names after the paper's where it has one: fi, ri, sf, del, gamma, lvt, rko, fac),
 * with units, defaults, ranges and one help sentence each. The host validates scene files
 * against this table and prints it with `sylva plugins --describe tree_aono_kunii`. */
#include "aono_config.h"
#include "tree_look.h"

#define MIN_MAX (SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX)
#define POSITIVE_MAX (SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_MIN_EXCLUSIVE | SYLVA_PARAM_HAS_MAX)

static const char *const pattern_choices[] = {"dichotomous", "monopodial", "ternary", "stochastic", NULL};
static const char *const law_choices[] = {"linear", "quadratic", "exponential", NULL};
static const char *const ri_method_choices[] = {"constant", "dimensions", "random", NULL};
static const char *const del_mode_choices[] = {"fixed", "spiral", NULL};
static const char *const leaf_placement_choices[] = {"tip", "along", NULL};

static const double def_fi[] = {0.0, 45.0};
static const double def_ri[] = {0.9, 0.8};
static const double def_ri_range[] = {0.5, 0.9};
static const double def_zero3[] = {0.0, 0.0, 0.0};
static const double def_leaf_color[] = {0.07, 0.16, 0.035};
static const double def_leaf_transmittance[] = {0.05, 0.13, 0.02};
static const double def_bark_color[] = {0.13, 0.10, 0.08};

static const sylva_param_spec fi_law_members[] = {
    {.name = "child", .type = SYLVA_P_INT, .flags = SYLVA_PARAM_REQUIRED | MIN_MAX, .min = 1, .max = 3,
     .help = "Which child's angle FI(i) this law gives (1, 2, or 3 for ternary and stochastic trees)."},
    {.name = "law", .type = SYLVA_P_ENUM, .flags = SYLVA_PARAM_REQUIRED, .choices = law_choices,
     .help = "linear (13) through two points, quadratic (14) fitted by least squares to three or more, "
             "exponential (15) through (0, phi(0)) and (n2, phi(n2))."},
    {.name = "points", .type = SYLVA_P_POLYLINE, .flags = SYLVA_PARAM_REQUIRED | MIN_MAX, .min = 0, .max = 180,
     .min_len = 2, .max_len = 64, .unit = "deg",
     .help = "Points [[n, phi], ...]: growth level n (1 for the trunk's children) and the angle there."},
};

static const sylva_param_spec controller_members[] = {
    {.name = "position", .type = SYLVA_P_VEC3, .flags = SYLVA_PARAM_REQUIRED, .unit = "m",
     .help = "The point controller Q(i) = [x, y, z] in the tree's own coordinates (trunk base at the origin)."},
    {.name = "fac", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_REQUIRED | MIN_MAX, .min = -1000, .max = 1000,
     .unit = "m",
     .help = "FAC(i): how far each child tip moves toward Q(i) (> 0, an attractor) or away from it (< 0, an "
             "inhibitor)."},
};

const sylva_param_spec aono_params[] = {
    /* structure */
    {.name = "levels", .type = SYLVA_P_INT, .flags = MIN_MAX, .def = 7, .min = 1, .max = AONO_MAX_LEVELS,
     .help = "Number of branching levels n of the full-grown tree (its age); younger variants have fewer."},
    {.name = "pattern", .type = SYLVA_P_ENUM, .def_str = "monopodial", .choices = pattern_choices,
     .help = "Branching pattern: dichotomous (two children, both deviate), monopodial (two, child LVT "
             "continues the mother), ternary (three), stochastic (two or three)."},
    {.name = "lvt", .type = SYLVA_P_INT, .flags = MIN_MAX, .def = 1, .min = 1, .max = 2,
     .help = "LVT: the child (1 or 2) that continues the mother's direction in the monopodial pattern."},
    {.name = "ternary_probability", .type = SYLVA_P_REAL, .flags = MIN_MAX, .def = 0.5, .min = 0, .max = 1,
     .help = "Stochastic pattern: the probability that a branching has three children instead of two."},
    /* dimensions */
    {.name = "trunk_length", .type = SYLVA_P_REAL, .flags = POSITIVE_MAX, .def = 4, .min = 0, .max = 1000,
     .unit = "m", .help = "H0: length of the trunk P_a P_b, the height of the first branching point."},
    {.name = "height", .type = SYLVA_P_REAL, .flags = POSITIVE_MAX, .def = 20, .min = 0, .max = 10000,
     .unit = "m", .help = "H: the tree's height, from which ri_method dimensions takes R1 = 1 - H0/H (23)."},
    {.name = "crown_diameter", .type = SYLVA_P_REAL, .flags = POSITIVE_MAX, .def = 12, .min = 0, .max = 10000,
     .unit = "m", .help = "L: the crown's diameter, from which ri_method dimensions takes the lateral ratio (24)."},
    {.name = "rko", .type = SYLVA_P_REAL, .flags = POSITIVE_MAX, .def = 1, .min = 0, .max = 1,
     .help = "RKO: with ri_method dimensions and dichotomous branching, R2 = RKO R1."},
    /* angles */
    {.name = "fi", .type = SYLVA_P_LIST, .flags = MIN_MAX, .min = 0, .max = 180, .def_list = def_fi, .def_len = 2,
     .min_len = 2, .max_len = 3, .unit = "deg",
     .help = "FI(i): constant branching angle of each child from its mother's direction (three entries for "
             "ternary and stochastic patterns)."},
    {.name = "fi_laws", .type = SYLVA_P_GROUP_LIST, .max_len = 3, .group = fi_law_members, .n_group = 3,
     .help = "Angles that vary with the level instead of FI(i): one law per child, [{child, law, points}]."},
    {.name = "sf", .type = SYLVA_P_REAL, .flags = MIN_MAX, .def = 0, .min = 0, .max = 90, .unit = "deg",
     .help = "SF: standard deviation of a normal deviation added to every branching angle."},
    {.name = "del", .type = SYLVA_P_REAL, .flags = MIN_MAX, .def = 137.5, .min = -360, .max = 360, .unit = "deg",
     .help = "DEL (delta): the angle of the first child's plane about its mother, from the frame's x' axis."},
    {.name = "del_mode", .type = SYLVA_P_ENUM, .def_str = "spiral", .choices = del_mode_choices,
     .help = "fixed: delta = DEL at every branching (16); spiral: delta = n DEL at level n, so successive "
             "branchings turn round the axis."},
    {.name = "gamma", .type = SYLVA_P_REAL, .flags = MIN_MAX, .def = 180, .min = -360, .max = 360, .unit = "deg",
     .help = "gamma: the second child's plane lies at delta + gamma (a third child's midway round the far side)."},
    /* contraction ratios */
    {.name = "ri_method", .type = SYLVA_P_ENUM, .def_str = "constant", .choices = ri_method_choices,
     .help = "Contraction ratios R_i: constant (ri), dimensions (from height, trunk_length, crown_diameter by "
             "(23)-(24)) or random (uniform in ri_range)."},
    {.name = "ri", .type = SYLVA_P_LIST, .flags = POSITIVE_MAX | SYLVA_PARAM_MAX_EXCLUSIVE, .min = 0, .max = 1,
     .def_list = def_ri, .def_len = 2, .min_len = 2, .max_len = 3,
     .help = "RI(i): constant ratio of each child's length to its mother's, rho_i = R_i rho_op."},
    {.name = "ri_range", .type = SYLVA_P_LIST, .flags = POSITIVE_MAX | SYLVA_PARAM_MAX_EXCLUSIVE, .min = 0, .max = 1,
     .def_list = def_ri_range, .def_len = 2, .min_len = 2, .max_len = 2,
     .help = "ri_method random: each ratio is drawn uniformly in [low, high] at every branching."},
    /* deviations */
    {.name = "deviation", .type = SYLVA_P_VEC3, .flags = MIN_MAX, .min = -1000, .max = 1000, .def_list = def_zero3,
     .def_len = 3, .unit = "m",
     .help = "(Dx, Dy, Dz): uniform deviation added to every child tip (25); Dz < 0 is gravity."},
    {.name = "controllers", .type = SYLVA_P_GROUP_LIST, .max_len = AONO_MAX_CONTROLLERS,
     .group = controller_members, .n_group = 2,
     .help = "Point controllers of (25): attractors and inhibitors (light, wind), [{position, fac}, ...]."},
    {.name = "preserve_length", .type = SYLVA_P_BOOL, .def = 1,
     .help = "Put every deviated child tip back at its length rho_i from the mother's tip (false: as (25) "
             "leaves it)."},
    /* thickness */
    {.name = "trunk_radius", .type = SYLVA_P_REAL, .flags = POSITIVE_MAX, .def = 0.25, .min = 0, .max = 100,
     .unit = "m", .help = "Radius of the trunk at its base."},
    {.name = "radius_reduction", .type = SYLVA_P_REAL, .flags = POSITIVE_MAX, .def = 0.7, .min = 0, .max = 1,
     .help = "Radius factor per branching level: a branch's tip radius is its base radius times this."},
    {.name = "lateral_radius_ratio", .type = SYLVA_P_REAL, .flags = POSITIVE_MAX, .def = 1, .min = 0, .max = 1,
     .help = "Extra radius factor on a child that does not continue its mother's axis (1: radius by level only)."},
    {.name = "sides", .type = SYLVA_P_INT, .flags = MIN_MAX, .def = 10, .min = 3, .max = 64,
     .help = "Polygon sides of the trunk's cross-section; thinner branches get fewer, in proportion to radius."},
    {.name = "min_sides", .type = SYLVA_P_INT, .flags = MIN_MAX, .def = 3, .min = 3, .max = 64,
     .help = "The fewest polygon sides of any branch."},
    /* leaves */
    {.name = "leaf_count", .type = SYLVA_P_INT, .flags = MIN_MAX, .def = 0, .min = 0, .max = 1000,
     .help = "Leaves on an outermost branch of the full-grown tree; other leaf-bearing branches get as many "
             "per metre (0: a bare tree)."},
    {.name = "leaf", .type = SYLVA_P_STRING, .def_str = "beech",
     .help = "The leaf drawn into the leaf texture, as affine maps: a preset (beech, maple, spruce, shrub, "
             "willow) or maps \"a b c d e f[ p]; ...\" of the leaf's unit square."},
    {.name = "leaf_length", .type = SYLVA_P_REAL, .flags = POSITIVE_MAX, .def = 0.12, .min = 0, .max = 10,
     .unit = "m", .help = "Side of the square leaf quad: the length of a leaf, stalk included (the maps give "
                          "its width)."},
    {.name = "leaf_placement", .type = SYLVA_P_ENUM, .def_str = "along", .choices = leaf_placement_choices,
     .help = "tip: leaves clustered at the tips of the leaf-bearing branches; along: spread along them."},
    {.name = "leaf_levels", .type = SYLVA_P_INT, .flags = MIN_MAX, .def = 1, .min = 1, .max = AONO_MAX_LEVELS,
     .help = "How many of the outermost branching levels bear leaves."},
    {.name = "leaf_angle", .type = SYLVA_P_REAL, .flags = MIN_MAX, .def = 50, .min = 0, .max = 180, .unit = "deg",
     .help = "Angle between a leaf and its branch."},
    {.name = "leaf_jitter", .type = SYLVA_P_REAL, .flags = MIN_MAX, .def = 20, .min = 0, .max = 90, .unit = "deg",
     .help = "Largest random turn of each leaf's direction and of its blade about it."},
    {.name = "leaf_color", .type = SYLVA_P_VEC3, .flags = MIN_MAX, .min = 0, .max = 1, .def_list = def_leaf_color,
     .def_len = 3, .help = "Linear RGB reflectance of the leaves (multiplied by the leaf texture's veins)."},
    {.name = "leaf_transmittance", .type = SYLVA_P_VEC3, .flags = MIN_MAX, .min = 0, .max = 1,
     .def_list = def_leaf_transmittance, .def_len = 3,
     .help = "Linear RGB diffuse transmittance of the leaves; plus leaf_color at most 1 per channel."},
    {.name = "bark_color", .type = SYLVA_P_VEC3, .flags = MIN_MAX, .min = 0, .max = 1, .def_list = def_bark_color,
     .def_len = 3, .help = "Linear RGB reflectance of the bark (multiplied by the bark texture)."},
    {.name = "bark", .type = SYLVA_P_ENUM, .def_str = "smooth", .choices = tree_look_bark_names,
     .help = "The fractal bark's preset: smooth, scaly, furrowed or fissured."},
    {.name = "bark_angle", .type = SYLVA_P_REAL, .flags = MIN_MAX, .def = 0, .min = -360, .max = 360,
     .unit = "deg", .help = "theta of the bark's lambda = e^(i theta); absent: the preset's own."},
};

_Static_assert(sizeof aono_params / sizeof aono_params[0] == AONO_N_PARAMS, "AONO_N_PARAMS counts the table");
