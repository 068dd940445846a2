/* eco_growth.h — the per-plant formulas of 004 §4.7–4.8 as MODELS.md corrects them:
 * favourability of a factor (4.22–4.25) and of the slope (4.21), vigour (4.20), relative power
 * (4.19) and power (4.18), growth by phases (4.32), ecological radius (4.33), death age (4.26)
 * and the dominance search radius N_opt (4.27). Pure functions, no state. */
#ifndef ECO_GROWTH_H
#define ECO_GROWTH_H

#include <stdint.h>

#include "eco_species.h"

/* (4.22–4.25) corrected: 1 when |x - opt| <= tol, else max(0, 1 - |x - opt| harm). */
double eco_favourability(double x, double opt, double tol, double harm);

/* (4.21): 1 - (f_s s)^2, clamped to [0, 1]. */
double eco_slope_favourability(double slope, double slope_harm);

/* The five favourabilities of a species at a patch whose factors are f (indexed by eco_factor:
 * altitude, slope, humidity, windiness, sunniness), in the same order. */
void eco_favourabilities(const eco_species *sp, const float f[5], double fav[5]);

/* (4.20): the mean of the five favourabilities. */
double eco_vigour(const double fav[5]);

/* (4.32): the height gained in a year by a plant of age t (years, before this year's birthday)
 * and vigour v. The printed intervals overlap at t_m and t_a; here phase 1 is t < t_m and phase
 * 2 is t_m <= t < t_a, so a plant of vigour 1 reaches h_m at t_m and 1 at t_a. */
double eco_growth(const eco_species *sp, double t, double v);

/* (4.18): power p = v h p_r. */
double eco_power(double v, double h, double p_r);

/* (4.26): t_max = t_m + (t_f - t_m) u, u uniform in [0, 1). */
double eco_death_age(const eco_species *sp, double u);

/* (4.27): N_opt = ceil(2 max R_s / K). */
uint32_t eco_n_opt(double max_r_s, double k);

#endif
