/* eco_species.c — sylva's profiles for the thesis's four species (beech, maple, spruce, shrubs)
 * and a generic one, and reading a species block (eco_schema.h) into an eco_species. */
#include "eco_species.h"

#include <stddef.h>
#include <string.h>

const char *const eco_profile_names[ECO_N_PROFILES + 1] = {"generic", "beech", "maple", "spruce", "shrub", NULL};

/* sylva's values (the thesis gives none), chosen so that 004 ch. 6's succession happens on a
 * terrain with a stream valley, a hill and high ground (scenes/succession_*.yaml): shrubs
 * spread first (t_m 3 years, g_s 25) but are weak (power grows with t_f, 4.19), broadleaves
 * begin to displace them at about 50 years (they outnumber them from 115: docs/models/ecology.md,
 * "Succession timing"), spruce advances later, and after ~180 years each holds its ground — maple the
 * humid valley, beech the middle altitudes, spruce the high, windy, less sunny ground, shrubs the
 * sunniest slopes. Altitude and humidity are normalised over the terrain; sunniness and
 * windiness are not, and lie near 0.5 and 1 on gentle terrain, hence the narrow tolerances.
 * Order of opt, tol and harm: altitude, slope (harm only: f_s), humidity, windiness, sunniness. */
const eco_species eco_profiles[ECO_N_PROFILES] = {
    [ECO_PROFILE_GENERIC] = {.opt = {ECO_GENERIC_OPT_ALTITUDE, 0, ECO_GENERIC_OPT_HUMIDITY, ECO_GENERIC_OPT_WINDINESS,
                                     ECO_GENERIC_OPT_SUNNINESS},
                             .tol = {ECO_GENERIC_TOL_ALTITUDE, 0, ECO_GENERIC_TOL_HUMIDITY, ECO_GENERIC_TOL_WINDINESS,
                                     ECO_GENERIC_TOL_SUNNINESS},
                             .harm = {ECO_GENERIC_HARM_ALTITUDE, ECO_GENERIC_HARM_SLOPE, ECO_GENERIC_HARM_HUMIDITY,
                                      ECO_GENERIC_HARM_WINDINESS, ECO_GENERIC_HARM_SUNNINESS},
                             .t_m = ECO_GENERIC_T_M, .t_a = ECO_GENERIC_T_A, .t_f = ECO_GENERIC_T_F, .h_m = ECO_GENERIC_H_M,
                             .r_s = ECO_GENERIC_R_S, .g_s = ECO_GENERIC_G_S, .p_s = ECO_GENERIC_P_S, .p_m = ECO_GENERIC_P_M,
                             .env_death = ECO_GENERIC_ENV_DEATH},
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

/* 1 when the scene gave `key` in the block (none: no block). */
static int given(plugin_params *reader, const char *key)
{
    return reader->block && plugin_param_given(reader, key);
}

int eco_species_read(plugin_params *reader, const char *name, eco_species *out, plugin_err *err)
{
    eco_profile prof = ECO_PROFILE_GENERIC;
    if (given(reader, "profile")) {
        prof = (eco_profile)plugin_param_int(reader, "profile");
    } else {
        for (int k = 0; k < ECO_N_PROFILES; k++)
            if (name && !strcmp(name, eco_profile_names[k])) prof = (eco_profile)k;
    }
    *out = eco_profiles[prof];
    for (size_t f = 0; reader->block && f < sizeof eco_species_fields / sizeof eco_species_fields[0]; f++) {
        if (given(reader, eco_species_fields[f].key))
            *(double *)((char *)out + eco_species_fields[f].offset) = plugin_param_real(reader, eco_species_fields[f].key);
    }
    if (reader->status) return reader->status;
    if (!(out->t_m < out->t_a))
        return plugin_fail_param(err, reader->block, given(reader, "t_m") ? "t_m" : "t_a",
                                 "species '%s': t_m = %g years is not before t_a = %g years; a plant matures "
                                 "(t_m) before it stops growing (t_a), so t_m < t_a", name, out->t_m, out->t_a);
    if (!(out->t_a <= out->t_f))
        return plugin_fail_param(err, reader->block, given(reader, "t_a") ? "t_a" : "t_f",
                                 "species '%s': t_a = %g years is after t_f = %g years; a plant stops growing "
                                 "(t_a) no later than it dies of age (t_f), so t_a <= t_f", name, out->t_a,
                                 out->t_f);
    return SYLVA_OK;
}
