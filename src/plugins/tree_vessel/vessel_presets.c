/* vessel_presets.c — preset values as scene-file keys. Beech, spruce and weeping willow carry
 * 004 §3.4's values exactly (decimal commas read as points; polylines as (order, value) points);
 * maple is sylva's. Keys not listed keep the schema's defaults: flat w polylines of value 1,
 * eight cone sides, no wind. */
#include "vessel_presets.h"

const char *const vessel_preset_names[VESSEL_PRESETS + 1] = {"beech", "spruce", "weeping_willow",
                                                             "maple", NULL};

#define NUM(key, v) {.param = key, .r = v}
#define WORD(key, v) {.param = key, .s = v}
#define LIST(key, ...)                                                                          \
    {.param = key, .list = (const double[]){__VA_ARGS__},                                       \
     .len = (uint32_t)(sizeof((const double[]){__VA_ARGS__}) / sizeof(double))}
/* A polyline: (order, value) pairs; len counts points. */
#define PL(key, ...)                                                                            \
    {.param = key, .list = (const double[]){__VA_ARGS__},                                       \
     .len = (uint32_t)(sizeof((const double[]){__VA_ARGS__}) / (2 * sizeof(double)))}
#define COUNT(t) (uint32_t)(sizeof t / sizeof t[0])

static const sylva_preset_value beech[] = {
    NUM("vessels", 4000), NUM("trunk_length", 5), NUM("thickness", 0.01),
    NUM("phyllotaxis", 85), NUM("gravicentralism", 0.3), NUM("leaf_size", 0.12),
    NUM("leaf_density", 16), WORD("leaf_type", "spiral"), NUM("leaf_spray", 5),
    PL("split_g", 0, 0.75, 15, 0.9),
    PL("angle_g", 0, 45, 15, 45),
    PL("length_min_g", 0, 1, 7.5, 0.45, 15, 1),
    PL("length_max_g", 0, 1, 15, 1),
    PL("length_scale_g", 0, 1, 15, 1),
    PL("gravimorphism_g", 0, 0, 15, 0),
    WORD("leaf", "beech"), WORD("bark", "smooth"),
    LIST("bark_color", 0.17, 0.165, 0.155),
    LIST("leaf_color", 0.07, 0.14, 0.035),
    LIST("leaf_transmittance", 0.06, 0.14, 0.03),
};

static const sylva_preset_value spruce[] = {
    NUM("vessels", 6000), NUM("trunk_length", 5.47), NUM("thickness", 0.005),
    NUM("phyllotaxis", 85), NUM("gravicentralism", 0.98), NUM("leaf_size", 0.1815),
    NUM("leaf_density", 30), WORD("leaf_type", "stacked"), NUM("leaf_spray", 1),
    PL("split_g", 0, 0.955, 0.7749, 0.9615, 1.827, 0.8288, 4.207, 0.8269, 15, 0.8294),
    PL("split_w", 0, 1, 42.89, 1.005, 42.89, 0.654, 50, 0.6256),
    PL("angle_g", 0, 128.8, 1.164, 17.91, 3.621, 45.21, 15, 35.83),
    PL("length_min_g", 0, 0.7109, 1.293, 0.8531, 15, 1),
    PL("length_max_g", 0, 0.9953, 15, 1),
    PL("length_scale_g", 0, 0.7109, 0.7749, 0.5385, 2.522, 1.327, 15, 1),
    PL("length_scale_w", 0, 1.014, 38.58, 1.014, 45.26, 0.5877, 50, 0.01896),
    PL("gravimorphism_g", 0, 0, 0.3875, 34.62, 1.034, -4.265, 1.55, -4.154, 2.974, -5.972, 15,
       -0.8532),
    NUM("sides", 6),
    WORD("leaf", "spruce"), WORD("bark", "scaly"),
    LIST("bark_color", 0.17, 0.11, 0.08),
    LIST("leaf_color", 0.030, 0.065, 0.030),
    LIST("leaf_transmittance", 0.010, 0.035, 0.010),
};

static const sylva_preset_value weeping_willow[] = {
    NUM("vessels", 1500), NUM("trunk_length", 1), NUM("thickness", 0.01),
    NUM("phyllotaxis", 85), NUM("gravicentralism", 0.2), NUM("leaf_size", 0.3452),
    NUM("leaf_density", 5), WORD("leaf_type", "coniferous"), NUM("leaf_spray", 1),
    PL("split_g", 0, 0.8507, 3.75, 0.7749, 15, 0.9),
    PL("angle_g", 0, 17.91, 1.875, 57.16, 15, 45),
    PL("length_min_g", 0, 1, 1.81, 0.9953, 15, 1),
    PL("length_min_w", 0, 0.9668, 50, 1),
    PL("length_max_g", 0, 0.9953, 1.422, 1.848, 15, 1),
    PL("length_scale_g", 0, 1, 15, 1),
    PL("length_scale_w", 0, 1, 22.63, 0.9953, 37.07, 0.7678, 50, 1),
    PL("gravimorphism_g", 0, 84.45, 1.746, 94.69, 15, 110),
    PL("gravimorphism_w", 0, 0.6446, 50, 1),
    WORD("leaf", "willow"), WORD("bark", "furrowed"),
    LIST("bark_color", 0.20, 0.17, 0.13),
    LIST("leaf_color", 0.11, 0.17, 0.05),
    LIST("leaf_transmittance", 0.10, 0.17, 0.04),
};

/* sylva's maple (not in 004): a shorter bole than the beech, a broad dome, opposite leaves
 * (pairs, phyllotaxis 90 degrees), larger lobed leaves, main limbs a little upright and the
 * outer shoots a little drooping. */
static const sylva_preset_value maple[] = {
    NUM("vessels", 2000), NUM("trunk_length", 4), NUM("thickness", 0.011),
    NUM("phyllotaxis", 90), NUM("gravicentralism", 0.5), NUM("leaf_size", 0.13),
    NUM("leaf_density", 8), WORD("leaf_type", "stacked"), NUM("leaf_spray", 1),
    PL("split_g", 0, 0.6, 3, 0.72, 15, 0.85),
    PL("angle_g", 0, 40, 3, 45, 15, 40),
    PL("length_min_g", 0, 1, 5, 0.75, 15, 0.85),
    PL("length_max_g", 0, 1, 15, 1),
    PL("length_scale_g", 0, 1, 15, 0.9),
    PL("gravimorphism_g", 0, 0, 1, 2, 15, 6),
    WORD("leaf", "maple"), WORD("bark", "fissured"),
    LIST("bark_color", 0.20, 0.18, 0.15),
    LIST("leaf_color", 0.08, 0.15, 0.035),
    LIST("leaf_transmittance", 0.08, 0.16, 0.03),
};

const sylva_preset vessel_presets[VESSEL_PRESETS] = {
    {"beech", "Beech, 004 §3.4.1; also the schema's defaults.", beech, COUNT(beech)},
    {"spruce", "Spruce, 004 §3.4.", spruce, COUNT(spruce)},
    {"weeping_willow", "Weeping willow, 004 §3.4.", weeping_willow, COUNT(weeping_willow)},
    {"maple", "sylva's maple (not in 004): a broad dome on a short bole, opposite lobed leaves.",
     maple, COUNT(maple)},
};
