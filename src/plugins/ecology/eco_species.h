/* eco_species.h — a species' ecological parameters (004 §4.7–4.8, MODELS.md §6): optima,
 * tolerances and harm factors of altitude, humidity, sunniness and windiness, slope harm, the
 * ages t_m, t_a, t_f, the height at maturity h_m, the radius per height R_s, the reproduction
 * factor g_s, the chance p_s of seeding near a parent, the death chance p_m when dominated, and
 * sylva's environmental death rate. The thesis prints no values: the profiles are sylva's.
 *
 * eco_species_read turns a validated species `ecology:` block (eco_schema.h) into an
 * eco_species, taking every key the scene does not give from the block's profile, and checks
 * what the schema cannot express.
 */
#ifndef ECO_SPECIES_H
#define ECO_SPECIES_H

#include <stdint.h>

#include "plugin_err.h"
#include "plugin_params.h"
#include "sylva/plugin.h"

/* Favourability terms of the vigour (4.20), indexed like the factor maps. The fifth, slope, has
 * a harm factor only (4.21). */
enum { ECO_FAV_ALTITUDE = 0, ECO_FAV_SLOPE = 1, ECO_FAV_HUMIDITY = 2, ECO_FAV_WINDINESS = 3, ECO_FAV_SUNNINESS = 4 };

typedef struct eco_species {
    double opt[5];        /* optimal ȳ_o, -, m_o, w_o, l_o (slope entry unused) */
    double tol[5];        /* tolerated deviation Δ (4.22–4.25) */
    double harm[5];       /* harm factor f per unit of deviation; [ECO_FAV_SLOPE] is f_s (4.21) */
    double t_m, t_a, t_f; /* maturity, end of growth, maximum age; years */
    double h_m;           /* normalised height at maturity, (0, 1] */
    double r_s;           /* ecological radius of a full-grown plant, metres (4.33) */
    double g_s;           /* reproduction factor (4.30) */
    double p_s;           /* chance that a seedling lands near a parent (Algorithm 7) */
    double p_m;           /* yearly death chance of a dominated plant */
    double env_death;     /* yearly death chance per fully unfavourable factor (sylva's rule) */
} eco_species;

/* The generic profile as constants: the species schema's defaults (eco_schema.c) are the same
 * numbers, and a static initialiser may only take constants, not members of eco_profiles. */
#define ECO_GENERIC_OPT_ALTITUDE 0.5
#define ECO_GENERIC_OPT_HUMIDITY 0.5
#define ECO_GENERIC_OPT_WINDINESS 0.5
#define ECO_GENERIC_OPT_SUNNINESS 0.5
#define ECO_GENERIC_TOL_ALTITUDE 0.3
#define ECO_GENERIC_TOL_HUMIDITY 0.3
#define ECO_GENERIC_TOL_WINDINESS 0.5
#define ECO_GENERIC_TOL_SUNNINESS 0.3
#define ECO_GENERIC_HARM_ALTITUDE 1.0
#define ECO_GENERIC_HARM_SLOPE 1.0
#define ECO_GENERIC_HARM_HUMIDITY 1.0
#define ECO_GENERIC_HARM_WINDINESS 1.0
#define ECO_GENERIC_HARM_SUNNINESS 1.0
#define ECO_GENERIC_T_M 20
#define ECO_GENERIC_T_A 60
#define ECO_GENERIC_T_F 150
#define ECO_GENERIC_H_M 0.5
#define ECO_GENERIC_R_S 4
#define ECO_GENERIC_G_S 4
#define ECO_GENERIC_P_S 0.8
#define ECO_GENERIC_P_M 0.2
#define ECO_GENERIC_ENV_DEATH 0.1

/* The profiles: default sets the `profile` key chooses. */
typedef enum eco_profile {
    ECO_PROFILE_GENERIC = 0,
    ECO_PROFILE_BEECH,
    ECO_PROFILE_MAPLE,
    ECO_PROFILE_SPRUCE,
    ECO_PROFILE_SHRUB,
    ECO_N_PROFILES
} eco_profile;

extern const char *const eco_profile_names[ECO_N_PROFILES + 1]; /* NULL-terminated */
extern const eco_species eco_profiles[ECO_N_PROFILES];

/* Reads a species block validated against eco_species_schema (eco_schema.h) through `reader`
 * (its block NULL: the species has none). The profile is the block's `profile` when given,
 * else the profile named like the species (`name`), else generic. Returns SYLVA_OK;
 * reader->status when the code read a name the schema lacks; or SYLVA_ERR_PARAM with err naming
 * the key and the rule (t_m before t_a, t_a at most t_f). */
int eco_species_read(plugin_params *reader, const char *name, eco_species *out, plugin_err *err);

#endif
