/* eco_species.c — the species block's schema, sylva's profiles for the thesis's four species
 * (beech, maple, spruce, shrubs) and a generic one, and reading a block into an eco_species. */
#include "eco_species.h"

#include <stddef.h>
#include <string.h>

const char *const eco_profile_names[ECO_N_PROFILES + 1] = {"generic", "beech", "maple", "spruce", "shrub", NULL};

/* sylva's values (the thesis gives none), chosen so that 004 ch. 6's succession happens on a
 * terrain with a stream valley, a hill and high ground (scenes/succession_*.yaml): shrubs
 * spread first (t_m 3 years, g_s 25) but are weak (power grows with t_f, 4.19), broadleaves
 * displace them, spruce advances later, and after ~180 years each holds its ground — maple the
 * humid valley, beech the middle altitudes, spruce the high, windy, less sunny ground, shrubs the
 * sunniest slopes. Altitude and humidity are normalised over the terrain; sunniness and
 * windiness are not, and lie near 0.5 and 1 on gentle terrain, hence the narrow tolerances.
 * Order of opt, tol and harm: altitude, slope (harm only: f_s), humidity, windiness, sunniness. */
const eco_species eco_profiles[ECO_N_PROFILES] = {
    [ECO_PROFILE_GENERIC] = {.opt = {0.5, 0, 0.5, 0.5, 0.5}, .tol = {0.3, 0, 0.3, 0.5, 0.3},
                             .harm = {1.0, 1.0, 1.0, 1.0, 1.0}, .t_m = 20, .t_a = 60, .t_f = 150, .h_m = 0.5,
                             .r_s = 4, .g_s = 4, .p_s = 0.8, .p_m = 0.2, .env_death = 0.1},
    [ECO_PROFILE_BEECH] = {.opt = {0.45, 0, 0.1, 0.8, 0.48}, .tol = {0.2, 0, 0.3, 0.3, 0.04},
                           .harm = {3.0, 6.0, 1.0, 1.0, 6.0}, .t_m = 18, .t_a = 100, .t_f = 300, .h_m = 0.4,
                           .r_s = 6, .g_s = 12, .p_s = 0.75, .p_m = 0.2, .env_death = 0.15},
    [ECO_PROFILE_MAPLE] = {.opt = {0.15, 0, 1.0, 0.7, 0.5}, .tol = {0.15, 0, 0.8, 0.4, 0.06},
                           .harm = {3.0, 6.0, 3.0, 1.0, 4.0}, .t_m = 12, .t_a = 70, .t_f = 250, .h_m = 0.45,
                           .r_s = 5, .g_s = 12, .p_s = 0.6, .p_m = 0.25, .env_death = 0.15},
    [ECO_PROFILE_SPRUCE] = {.opt = {0.85, 0, 0.1, 1.0, 0.44}, .tol = {0.2, 0, 0.4, 0.3, 0.06},
                            .harm = {3.0, 5.0, 1.0, 1.0, 4.0}, .t_m = 20, .t_a = 90, .t_f = 250, .h_m = 0.35,
                            .r_s = 3.5, .g_s = 10, .p_s = 0.7, .p_m = 0.25, .env_death = 0.15},
    [ECO_PROFILE_SHRUB] = {.opt = {0.3, 0, 0.1, 1.0, 0.55}, .tol = {0.35, 0, 0.5, 0.5, 0.05},
                           .harm = {1.5, 1.0, 1.0, 1.0, 4.0}, .t_m = 3, .t_a = 8, .t_f = 30, .h_m = 0.6,
                           .r_s = 1.5, .g_s = 25, .p_s = 0.85, .p_m = 0.6, .env_death = 0.1},
};

#define G (eco_profiles[ECO_PROFILE_GENERIC])
#define RANGE (SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX)
#define POSITIVE (SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_MIN_EXCLUSIVE | SYLVA_PARAM_HAS_MAX)
#define FACTOR_KEYS(NAME, IDX, WHAT)                                                                   \
    {.name = NAME "_opt", .type = SYLVA_P_REAL, .flags = RANGE, .def = G.opt[IDX], .min = 0, .max = 1,    \
     .help = "Optimal " WHAT " (normalised over the terrain, 0 to 1); default from the profile."},        \
    {.name = NAME "_tol", .type = SYLVA_P_REAL, .flags = RANGE, .def = G.tol[IDX], .min = 0, .max = 1,    \
     .help = "Deviation from the optimal " WHAT " that does no harm; default from the profile."},         \
    {.name = NAME "_harm", .type = SYLVA_P_REAL, .flags = RANGE, .def = G.harm[IDX], .min = 0, .max = 100, \
     .help = "Loss of favourability per unit of " WHAT " deviation beyond the tolerance; default from "    \
             "the profile."}

const sylva_param_spec eco_species_schema[ECO_SPECIES_KEYS] = {
    {.name = "profile", .type = SYLVA_P_ENUM, .def_str = "generic", .choices = eco_profile_names,
     .help = "Default values of every other key: generic, beech, maple, spruce or shrub; when not given, "
             "the profile named like the species, else generic."},
    FACTOR_KEYS("altitude", ECO_FAV_ALTITUDE, "altitude"),
    FACTOR_KEYS("humidity", ECO_FAV_HUMIDITY, "humidity"),
    FACTOR_KEYS("sunniness", ECO_FAV_SUNNINESS, "sunniness"),
    FACTOR_KEYS("windiness", ECO_FAV_WINDINESS, "windiness"),
    {.name = "slope_harm", .type = SYLVA_P_REAL, .flags = RANGE, .def = G.harm[ECO_FAV_SLOPE], .min = 0,
     .max = 100, .help = "Slope harm f_s: favourability 1 - (f_s slope)^2; default from the profile."},
    {.name = "t_m", .type = SYLVA_P_REAL, .flags = POSITIVE, .def = G.t_m, .min = 0, .max = 10000, .unit = "years",
     .help = "Age at maturity, when the plant first seeds; default from the profile."},
    {.name = "t_a", .type = SYLVA_P_REAL, .flags = POSITIVE, .def = G.t_a, .min = 0, .max = 10000, .unit = "years",
     .help = "Age at which the plant stops growing (after t_m); default from the profile."},
    {.name = "t_f", .type = SYLVA_P_REAL, .flags = POSITIVE, .def = G.t_f, .min = 0, .max = 10000, .unit = "years",
     .help = "Greatest age a plant of the species reaches (at least t_a); default from the profile."},
    {.name = "h_m", .type = SYLVA_P_REAL, .flags = POSITIVE, .def = G.h_m, .min = 0, .max = 1,
     .help = "Height at maturity as a share of the full-grown height; default from the profile."},
    {.name = "r_s", .type = SYLVA_P_REAL, .flags = POSITIVE, .def = G.r_s, .min = 0, .max = 20, .unit = "m",
     .help = "Ecological radius of a full-grown plant (the radius is height times r_s); default from the "
             "profile."},
    {.name = "g_s", .type = SYLVA_P_REAL, .flags = RANGE, .def = G.g_s, .min = 0, .max = 100,
     .help = "Reproduction factor: seedlings a year per unit of mature plants' power; default from the "
             "profile."},
    {.name = "p_s", .type = SYLVA_P_REAL, .flags = RANGE, .def = G.p_s, .min = 0, .max = 1,
     .help = "Chance that a seedling lands beside a parent rather than anywhere; default from the profile."},
    {.name = "p_m", .type = SYLVA_P_REAL, .flags = RANGE, .def = G.p_m, .min = 0, .max = 1,
     .help = "Yearly chance that a dominated plant dies; default from the profile."},
    {.name = "env_death", .type = SYLVA_P_REAL, .flags = RANGE, .def = G.env_death, .min = 0, .max = 1,
     .help = "Yearly death chance for each terrain factor, times one minus that factor's favourability; "
             "default from the profile."},
};

/* Where each key of the schema (after `profile`) goes in an eco_species. */
static const struct {
    const char *key;
    size_t offset;
} eco_species_fields[] = {
    {"altitude_opt", offsetof(eco_species, opt[ECO_FAV_ALTITUDE])},
    {"altitude_tol", offsetof(eco_species, tol[ECO_FAV_ALTITUDE])},
    {"altitude_harm", offsetof(eco_species, harm[ECO_FAV_ALTITUDE])},
    {"humidity_opt", offsetof(eco_species, opt[ECO_FAV_HUMIDITY])},
    {"humidity_tol", offsetof(eco_species, tol[ECO_FAV_HUMIDITY])},
    {"humidity_harm", offsetof(eco_species, harm[ECO_FAV_HUMIDITY])},
    {"sunniness_opt", offsetof(eco_species, opt[ECO_FAV_SUNNINESS])},
    {"sunniness_tol", offsetof(eco_species, tol[ECO_FAV_SUNNINESS])},
    {"sunniness_harm", offsetof(eco_species, harm[ECO_FAV_SUNNINESS])},
    {"windiness_opt", offsetof(eco_species, opt[ECO_FAV_WINDINESS])},
    {"windiness_tol", offsetof(eco_species, tol[ECO_FAV_WINDINESS])},
    {"windiness_harm", offsetof(eco_species, harm[ECO_FAV_WINDINESS])},
    {"slope_harm", offsetof(eco_species, harm[ECO_FAV_SLOPE])},
    {"t_m", offsetof(eco_species, t_m)},
    {"t_a", offsetof(eco_species, t_a)},
    {"t_f", offsetof(eco_species, t_f)},
    {"h_m", offsetof(eco_species, h_m)},
    {"r_s", offsetof(eco_species, r_s)},
    {"g_s", offsetof(eco_species, g_s)},
    {"p_s", offsetof(eco_species, p_s)},
    {"p_m", offsetof(eco_species, p_m)},
    {"env_death", offsetof(eco_species, env_death)},
};

/* 1 when the scene gave `key` in the block. */
static int given(const sylva_params *block, const char *key)
{
    const sylva_value *v = block ? sylva_param(block, key) : NULL;
    return v && v->is_set;
}

int eco_species_read(const sylva_host_api *api, sylva_host *host, const sylva_params *block, const char *name,
                     eco_species *out)
{
    eco_profile prof = ECO_PROFILE_GENERIC;
    if (given(block, "profile")) {
        prof = (eco_profile)sylva_param(block, "profile")->i;
    } else {
        for (int k = 0; k < ECO_N_PROFILES; k++)
            if (name && !strcmp(name, eco_profile_names[k])) prof = (eco_profile)k;
    }
    *out = eco_profiles[prof];
    for (size_t f = 0; block && f < sizeof eco_species_fields / sizeof eco_species_fields[0]; f++) {
        if (given(block, eco_species_fields[f].key))
            *(double *)((char *)out + eco_species_fields[f].offset) = sylva_param(block, eco_species_fields[f].key)->r;
    }
    if (!(out->t_m < out->t_a))
        return api->param_error(host, block, given(block, "t_m") ? "t_m" : "t_a",
                                "species '%s': t_m = %g years is not before t_a = %g years; a plant matures "
                                "(t_m) before it stops growing (t_a), so t_m < t_a", name, out->t_m, out->t_a);
    if (!(out->t_a <= out->t_f))
        return api->param_error(host, block, given(block, "t_a") ? "t_a" : "t_f",
                                "species '%s': t_a = %g years is after t_f = %g years; a plant stops growing "
                                "(t_a) no later than it dies of age (t_f), so t_a <= t_f", name, out->t_a,
                                out->t_f);
    return SYLVA_OK;
}
