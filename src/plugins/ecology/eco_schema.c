/* eco_schema.c — the ecology plugin's parameter tables: the scene's `ecology:` block
 * (eco_params) and the `ecology:` block each species carries (eco_species_schema, whose
 * defaults are the generic profile of eco_species.h). Static const data. */
#include "eco_schema.h"

#include "eco_species.h"

#define RANGE (SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX)
#define POSITIVE (SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_MIN_EXCLUSIVE | SYLVA_PARAM_HAS_MAX)
#define FACTOR_KEYS(NAME, IDX, WHAT)                                                                   \
    {.name = NAME "_opt", .type = SYLVA_P_REAL, .flags = RANGE, .def = ECO_GENERIC_OPT_##IDX, .min = 0, .max = 1, \
     .help = "Optimal " WHAT " (normalised over the terrain, 0 to 1); default from the profile."},        \
    {.name = NAME "_tol", .type = SYLVA_P_REAL, .flags = RANGE, .def = ECO_GENERIC_TOL_##IDX, .min = 0, .max = 1,    \
     .help = "Deviation from the optimal " WHAT " that does no harm; default from the profile."},         \
    {.name = NAME "_harm", .type = SYLVA_P_REAL, .flags = RANGE, .def = ECO_GENERIC_HARM_##IDX, .min = 0, .max = 100, \
     .help = "Loss of favourability per unit of " WHAT " deviation beyond the tolerance; default from "    \
             "the profile."}

const sylva_param_spec eco_species_schema[ECO_SPECIES_KEYS] = {
    {.name = "profile", .type = SYLVA_P_ENUM, .def_str = "generic", .choices = eco_profile_names,
     .help = "Default values of every other key: generic, beech, maple, spruce or shrub; when not given, "
             "the profile named like the species, else generic."},
    FACTOR_KEYS("altitude", ALTITUDE, "altitude"),
    FACTOR_KEYS("humidity", HUMIDITY, "humidity"),
    FACTOR_KEYS("sunniness", SUNNINESS, "sunniness"),
    FACTOR_KEYS("windiness", WINDINESS, "windiness"),
    {.name = "slope_harm", .type = SYLVA_P_REAL, .flags = RANGE, .def = ECO_GENERIC_HARM_SLOPE, .min = 0,
     .max = 100, .help = "Slope harm f_s: favourability 1 - (f_s slope)^2; default from the profile."},
    {.name = "t_m", .type = SYLVA_P_REAL, .flags = POSITIVE, .def = ECO_GENERIC_T_M, .min = 0, .max = 10000, .unit = "years",
     .help = "Age at maturity, when the plant first seeds; default from the profile."},
    {.name = "t_a", .type = SYLVA_P_REAL, .flags = POSITIVE, .def = ECO_GENERIC_T_A, .min = 0, .max = 10000, .unit = "years",
     .help = "Age at which the plant stops growing (after t_m); default from the profile."},
    {.name = "t_f", .type = SYLVA_P_REAL, .flags = POSITIVE, .def = ECO_GENERIC_T_F, .min = 0, .max = 10000, .unit = "years",
     .help = "Greatest age a plant of the species reaches (at least t_a); default from the profile."},
    {.name = "h_m", .type = SYLVA_P_REAL, .flags = POSITIVE, .def = ECO_GENERIC_H_M, .min = 0, .max = 1,
     .help = "Height at maturity as a share of the full-grown height; default from the profile."},
    {.name = "r_s", .type = SYLVA_P_REAL, .flags = POSITIVE, .def = ECO_GENERIC_R_S, .min = 0, .max = 20, .unit = "m",
     .help = "Ecological radius of a full-grown plant (the radius is height times r_s); default from the "
             "profile."},
    {.name = "g_s", .type = SYLVA_P_REAL, .flags = RANGE, .def = ECO_GENERIC_G_S, .min = 0, .max = 100,
     .help = "Reproduction factor: seedlings a year per unit of mature plants' power; default from the "
             "profile."},
    {.name = "p_s", .type = SYLVA_P_REAL, .flags = RANGE, .def = ECO_GENERIC_P_S, .min = 0, .max = 1,
     .help = "Chance that a seedling lands beside a parent rather than anywhere; default from the profile."},
    {.name = "p_m", .type = SYLVA_P_REAL, .flags = RANGE, .def = ECO_GENERIC_P_M, .min = 0, .max = 1,
     .help = "Yearly chance that a dominated plant dies; default from the profile."},
    {.name = "env_death", .type = SYLVA_P_REAL, .flags = RANGE, .def = ECO_GENERIC_ENV_DEATH, .min = 0, .max = 1,
     .help = "Yearly death chance for each terrain factor, times one minus that factor's favourability; "
             "default from the profile."},
};

const sylva_param_spec eco_params[ECO_PARAMS] = {
    {.name = "years", .type = SYLVA_P_INT, .flags = RANGE, .def = 180, .min = 0, .max = 100000, .unit = "years",
     .help = "Years of succession to simulate from bare land."},
    {.name = "species", .type = SYLVA_P_STRING,
     .help = "Species that take part, by name, separated by commas or spaces; empty: every species of the scene."},
    {.name = "patches", .type = SYLVA_P_INT, .flags = RANGE, .def = 100, .min = 2, .max = 2048,
     .help = "Patches of the factor grid along the terrain's longer side (the thesis uses 100)."},
    {.name = "growth_area", .type = SYLVA_P_LIST, .flags = SYLVA_PARAM_HAS_MIN, .min = 0, .max_len = 4,
     .help = "Patch rectangle [i0, k0, i1, k1] (whole numbers, inclusive, i west to east, k south to north) "
             "where plants may grow; empty: the whole terrain."},
    {.name = "growth_mask", .type = SYLVA_P_GRID,
     .help = "Rows (south to north) of cells over the whole terrain; plants grow only on patches whose centre "
             "falls in a non-zero cell."},
    {.name = "edge_fade", .type = SYLVA_P_REAL, .flags = RANGE, .def = 150, .min = 0, .max = 100000, .unit = "m",
     .help = "Width of the band round the growth area or mask where seedlings take root less and less often, "
             "its edge broken by noise (0: a hard edge)."},
    {.name = "water_altitude", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0, .min = 0, .max = 1,
     .help = "Normalised altitude below which patches are water (0: only the terrain's own water surface)."},
    {.name = "rain", .type = SYLVA_P_REAL, .flags = RANGE, .def = 1, .min = 0, .max = 1000,
     .help = "Precipitation every patch receives, m_climate."},
    {.name = "water_humidity", .type = SYLVA_P_REAL, .flags = RANGE, .def = 10, .min = 0, .max = 1000000,
     .help = "Humidity added to water patches, m_w."},
    {.name = "runoff", .type = SYLVA_P_REAL, .flags = RANGE, .def = 1, .min = 0, .max = 1,
     .help = "Runoff strength k_m: share of a patch's water times its slope that flows to lower patches."},
    {.name = "humidity_blur", .type = SYLVA_P_INT, .flags = RANGE, .def = 10, .min = 0, .max = 1000,
     .help = "Passes of the 5-point average over the humidity, N_mblur."},
    {.name = "wind_azimuth", .type = SYLVA_P_REAL, .flags = RANGE, .def = 270, .min = -360, .max = 360,
     .unit = "deg", .help = "Direction the wind comes from, clockwise from north (270: from the west)."},
    {.name = "wind_samples", .type = SYLVA_P_INT, .flags = RANGE, .def = 10, .min = 1, .max = 1000,
     .help = "Patches marched upwind to find a patch's shelter, N_w."},
    {.name = "shelter_angle", .type = SYLVA_P_REAL,
     .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_MIN_EXCLUSIVE | SYLVA_PARAM_HAS_MAX, .def = 45, .min = 0, .max = 90,
     .unit = "deg", .help = "Shelter angle at which a patch is out of the wind entirely, Theta_0."},
    {.name = "latitude", .type = SYLVA_P_REAL, .flags = RANGE, .def = 46, .min = -80, .max = 80, .unit = "deg",
     .help = "Latitude of the terrain (north positive); sets the summer sun's path."},
    {.name = "sun_samples", .type = SYLVA_P_INT, .flags = RANGE, .def = 9, .min = 3, .max = 101,
     .help = "Sun positions along the day, an odd number, N_l."},
    {.name = "ambient", .type = SYLVA_P_REAL,
     .flags = RANGE | SYLVA_PARAM_MIN_EXCLUSIVE | SYLVA_PARAM_MAX_EXCLUSIVE, .def = 0.2, .min = 0, .max = 1,
     .help = "Share of the light a patch gets in shadow or facing away from the sun, l_ambient."},
    {.name = "stream_seeds", .type = SYLVA_P_LIST, .flags = RANGE, .min = 0, .max = 9007199254740992.0,
     .max_len = 13,
     .help = "Seeds of the 13 random streams (near, parent, side, anywhere, position i, position j, death by "
             "dominance, altitude, humidity, sunniness, windiness, slope, death age); empty: all 0."},
    {.name = "min_height", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0.5, .min = 0, .max = 1000, .unit = "m",
     .help = "Plants shorter than this are left out of the scene (they still live in the simulation)."},
    {.name = "max_plants", .type = SYLVA_P_INT, .flags = RANGE, .def = 5000000, .min = 1, .max = 100000000,
     .help = "Most living plants the simulation may hold; more is an error."},
    {.name = "threads", .type = SYLVA_P_INT, .flags = RANGE, .def = 0, .min = 0, .max = 256,
     .help = "Worker threads (0: the run's --threads, else one per processor); the forest does not depend on it."},
};
