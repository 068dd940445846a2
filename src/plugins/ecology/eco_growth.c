/* eco_growth.c — favourability, vigour, power, growth phases, death age and N_opt. */
#include "eco_growth.h"

#include <math.h>

#include "eco_terrain.h"

double eco_favourability(double x, double opt, double tol, double harm)
{
    double d = fabs(x - opt);
    if (d <= tol) return 1.0;
    /* The printed 1 - max{1, d f} is never positive; the minimum with 1 is meant. */
    double c = 1.0 - d * harm;
    return c > 0 ? c : 0.0;
}

double eco_slope_favourability(double slope, double slope_harm)
{
    double q = slope_harm * slope;
    double c = 1.0 - q * q;
    return c < 0 ? 0 : c > 1 ? 1 : c;
}

void eco_favourabilities(const eco_species *sp, const float f[5], double fav[5])
{
    static const int terms[4] = {ECO_FAV_ALTITUDE, ECO_FAV_HUMIDITY, ECO_FAV_WINDINESS, ECO_FAV_SUNNINESS};
    static const int factors[4] = {ECO_ALTITUDE, ECO_HUMIDITY, ECO_WINDINESS, ECO_SUNNINESS};
    for (int q = 0; q < 4; q++)
        fav[terms[q]] = eco_favourability(f[factors[q]], sp->opt[terms[q]], sp->tol[terms[q]], sp->harm[terms[q]]);
    fav[ECO_FAV_SLOPE] = eco_slope_favourability(f[ECO_SLOPE], sp->harm[ECO_FAV_SLOPE]);
}

double eco_vigour(const double fav[5])
{
    return (fav[0] + fav[1] + fav[2] + fav[3] + fav[4]) / 5.0;
}

double eco_growth(const eco_species *sp, double t, double v)
{
    if (t < sp->t_m) return v * sp->h_m / sp->t_m;
    if (t < sp->t_a) return v * (1.0 - sp->h_m) / (sp->t_a - sp->t_m);
    return 0.0;
}

double eco_power(double v, double h, double p_r) { return v * h * p_r; }

double eco_death_age(const eco_species *sp, double u) { return sp->t_m + (sp->t_f - sp->t_m) * u; }

uint32_t eco_n_opt(double max_r_s, double k)
{
    double n = ceil(2.0 * max_r_s / k);
    return n < 1 ? 1u : n > 1e6 ? 1000000u : (uint32_t)n;
}
