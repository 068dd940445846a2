/* sky.c — the Preetham, Shirley and Smits (1999) daylight sky and a tabulated sky for
 * importance sampling. Owns the model's coefficients, its clamps (sun and view directions at
 * the horizon), the ground colour below the horizon, and the lat-long sampling table. It
 * knows nothing of the sun disc itself: that is the integrator's separate light.
 * See docs/models/sky.md for the equations and the sampling scheme.
 */
#include "render/sky.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Views at the horizon: cos(theta) is held at or above this so that B / cos(theta) in the Perez
 * function stays finite (theta <= 89.94 degrees). B is negative over the whole turbidity
 * range, so exp(B / cos theta) is already below 1e-70 there and the clamp changes nothing
 * visible. */
#define SKY_COS_THETA_MIN 1e-3

/* Ground colour: the sky is averaged over SKY_GROUND_BANDS elevations (midpoints of one-degree
 * bands from 0 to 5 degrees) times SKY_GROUND_AZIMUTHS equally spaced azimuths. */
#define SKY_GROUND_BANDS 5
#define SKY_GROUND_AZIMUTHS 72

/* Importance floor: cells with any radiance get (luminance + floor) as weight, the floor being
 * this fraction of the solid-angle mean luminance. */
#define SKY_TABLE_FLOOR 0.01
/* Samples stay this fraction of a cell's angular size away from its edges in theta and phi, so
 * that a direction rounded to float is found in the cell it was drawn from. */
#define SKY_TABLE_EDGE 1e-3

static double clampd(double v, double lo, double hi) { return v < lo ? lo : (v > hi ? hi : v); }

/* Perez et al. F with cos(theta) given (already clamped) and gamma, cos(gamma). */
static double perez_eval(const double c[5], double cos_theta, double gamma, double cos_gamma)
{
    return (1.0 + c[0] * exp(c[1] / cos_theta)) *
           (1.0 + c[2] * exp(c[3] * gamma) + c[4] * cos_gamma * cos_gamma);
}

double sky_perez(const double c[5], double theta, double gamma)
{
    double cos_theta = cos(theta);
    if (cos_theta < SKY_COS_THETA_MIN) cos_theta = SKY_COS_THETA_MIN;
    return perez_eval(c, cos_theta, gamma, cos(gamma));
}

void sky_preetham_zenith(double turbidity, double theta_s, double Yxy[3])
{
    double T = turbidity, ts = clampd(theta_s, 0.0, M_PI / 2);
    double ts2 = ts * ts, ts3 = ts2 * ts;
    /* Appendix A.2: zenith luminance (kcd/m^2) and chromaticity. */
    double chi = (4.0 / 9.0 - T / 120.0) * (M_PI - 2.0 * ts);
    Yxy[0] = (4.0453 * T - 4.9710) * tan(chi) - 0.2155 * T + 2.4192;
    Yxy[1] = T * T * (0.00166 * ts3 - 0.00375 * ts2 + 0.00209 * ts) +
             T * (-0.02903 * ts3 + 0.06377 * ts2 - 0.03202 * ts + 0.00394) +
             (0.11693 * ts3 - 0.21196 * ts2 + 0.06052 * ts + 0.25886);
    Yxy[2] = T * T * (0.00275 * ts3 - 0.00610 * ts2 + 0.00317 * ts) +
             T * (-0.04214 * ts3 + 0.08970 * ts2 - 0.04153 * ts + 0.00516) +
             (0.15346 * ts3 - 0.26756 * ts2 + 0.06670 * ts + 0.26688);
}

/* Appendix A.2: the Perez coefficients A..E as linear functions of turbidity. */
static void preetham_coefficients(sky_preetham *s, double T)
{
    s->perez_Y[0] = 0.1787 * T - 1.4630;
    s->perez_Y[1] = -0.3554 * T + 0.4275;
    s->perez_Y[2] = -0.0227 * T + 5.3251;
    s->perez_Y[3] = 0.1206 * T - 2.5771;
    s->perez_Y[4] = -0.0670 * T + 0.3703;

    s->perez_x[0] = -0.0193 * T - 0.2592;
    s->perez_x[1] = -0.0665 * T + 0.0008;
    s->perez_x[2] = -0.0004 * T + 0.2125;
    s->perez_x[3] = -0.0641 * T - 0.8989;
    s->perez_x[4] = -0.0033 * T + 0.0452;

    s->perez_y[0] = -0.0167 * T - 0.2608;
    s->perez_y[1] = -0.0950 * T + 0.0092;
    s->perez_y[2] = -0.0079 * T + 0.2102;
    s->perez_y[3] = -0.0441 * T - 1.6537;
    s->perez_y[4] = -0.0109 * T + 0.0529;
}

/* Yxy (Y already in sylva's radiance unit) to linear sRGB (Rec. 709 primaries, D65 white).
 * Components outside the gamut are clamped to 0. */
static void yxy_to_rgb(double Y, double x, double y, double rgb[3])
{
    double X = x / y * Y, Z = (1.0 - x - y) / y * Y;
    rgb[0] = 3.2404542 * X - 1.5371385 * Y - 0.4985314 * Z;
    rgb[1] = -0.9692660 * X + 1.8760108 * Y + 0.0415560 * Z;
    rgb[2] = 0.0556434 * X - 0.2040259 * Y + 1.0572252 * Z;
    for (int k = 0; k < 3; k++)
        if (!(rgb[k] > 0.0)) rgb[k] = 0.0;
}

/* The sky above the horizon; dir[2] is taken as >= 0. */
static void preetham_sky(const sky_preetham *s, const double dir[3], double rgb[3])
{
    double cos_theta = dir[2] < SKY_COS_THETA_MIN ? SKY_COS_THETA_MIN : dir[2];
    double cos_gamma = clampd(dir[0] * s->sun_dir[0] + dir[1] * s->sun_dir[1] +
                                  dir[2] * s->sun_dir[2], -1.0, 1.0);
    double gamma = acos(cos_gamma);
    /* Section 3 / appendix A.2: value = zenith value * F(theta, gamma) / F(0, theta_s). */
    double Y = s->zenith_Yxy[0] * perez_eval(s->perez_Y, cos_theta, gamma, cos_gamma) / s->denom_Y;
    double x = s->zenith_Yxy[1] * perez_eval(s->perez_x, cos_theta, gamma, cos_gamma) / s->denom_x;
    double y = s->zenith_Yxy[2] * perez_eval(s->perez_y, cos_theta, gamma, cos_gamma) / s->denom_y;
    yxy_to_rgb(Y / 100.0 * s->scale, x, y, rgb);
}

int sky_preetham_init(sky_preetham *s, const double sun_dir[3], double turbidity, double scale,
                      double ground_albedo)
{
    if (!(turbidity >= 1.7 && turbidity <= 10.0)) return -1;
    if (!(scale >= 0.0 && scale <= DBL_MAX)) return -1;
    if (!(ground_albedo >= 0.0 && ground_albedo <= 1.0)) return -1;
    double len = sqrt(sun_dir[0] * sun_dir[0] + sun_dir[1] * sun_dir[1] + sun_dir[2] * sun_dir[2]);
    if (!(len > 0.0 && len <= DBL_MAX)) return -1;

    memset(s, 0, sizeof *s);
    double d[3] = {sun_dir[0] / len, sun_dir[1] / len, sun_dir[2] / len};
    if (d[2] < 0.0) {
        /* Sun below the horizon: the formulae see it on the horizon at the same azimuth
         * (theta_s = pi/2); straight down has no azimuth and is put at +X. */
        double h = sqrt(d[0] * d[0] + d[1] * d[1]);
        if (h > 1e-12) {
            d[0] /= h;
            d[1] /= h;
        } else {
            d[0] = 1.0;
            d[1] = 0.0;
        }
        d[2] = 0.0;
    }
    memcpy(s->sun_dir, d, sizeof d);
    s->turbidity = turbidity;
    s->scale = scale;
    s->theta_s = acos(clampd(d[2], 0.0, 1.0));
    sky_preetham_zenith(turbidity, s->theta_s, s->zenith_Yxy);
    preetham_coefficients(s, turbidity);
    s->denom_Y = sky_perez(s->perez_Y, 0.0, s->theta_s);
    s->denom_x = sky_perez(s->perez_x, 0.0, s->theta_s);
    s->denom_y = sky_perez(s->perez_y, 0.0, s->theta_s);

    double sum[3] = {0.0, 0.0, 0.0};
    for (int b = 0; b < SKY_GROUND_BANDS; b++) {
        double elev = (b + 0.5) * (M_PI / 180.0);
        for (int a = 0; a < SKY_GROUND_AZIMUTHS; a++) {
            double phi = (a + 0.5) * (2.0 * M_PI / SKY_GROUND_AZIMUTHS);
            double v[3] = {cos(elev) * cos(phi), cos(elev) * sin(phi), sin(elev)};
            double c[3];
            preetham_sky(s, v, c);
            for (int k = 0; k < 3; k++) sum[k] += c[k];
        }
    }
    for (int k = 0; k < 3; k++)
        s->ground_rgb[k] = ground_albedo * sum[k] / (SKY_GROUND_BANDS * SKY_GROUND_AZIMUTHS);
    return 0;
}

void sky_preetham_radiance(const sky_preetham *s, const double dir[3], double rgb[3])
{
    if (dir[2] < 0.0) {
        memcpy(rgb, s->ground_rgb, 3 * sizeof(double));
        return;
    }
    preetham_sky(s, dir, rgb);
}

/* --- the tabulated sky ------------------------------------------------------------------- */

void sky_table_free(sky_table *t)
{
    if (!t) return;
    free(t->rgb);
    free(t->cdf_rows);
    free(t->cdf_cols);
    free(t->pdf);
    memset(t, 0, sizeof *t);
}

static double cell_importance(const float c[3])
{
    double r = isfinite(c[0]) && c[0] > 0.0f ? c[0] : 0.0;
    double g = isfinite(c[1]) && c[1] > 0.0f ? c[1] : 0.0;
    double b = isfinite(c[2]) && c[2] > 0.0f ? c[2] : 0.0;
    return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}

int sky_table_build(sky_table *t, uint32_t nt, uint32_t np,
                    void (*radiance)(const double dir[3], double rgb[3], const void *user),
                    const void *user)
{
    memset(t, 0, sizeof *t);
    if (nt == 0 || np == 0 || !radiance) return -1;
    size_t cells = (size_t)nt * np;
    if (cells > SIZE_MAX / (3 * sizeof(float)) / 2) return -1;

    int rc = -1;
    double *weight = malloc(cells * sizeof *weight); /* owned here, freed below */
    double *row_sum = malloc((size_t)nt * sizeof *row_sum); /* owned here, freed below */
    t->nt = nt;
    t->np = np;
    t->rgb = malloc(cells * 3 * sizeof *t->rgb);
    t->cdf_rows = malloc(((size_t)nt + 1) * sizeof *t->cdf_rows);
    t->cdf_cols = malloc((size_t)nt * ((size_t)np + 1) * sizeof *t->cdf_cols);
    t->pdf = malloc(cells * sizeof *t->pdf);
    if (!weight || !row_sum || !t->rgb || !t->cdf_rows || !t->cdf_cols || !t->pdf) goto done;

    double dtheta = M_PI / nt, dphi = 2.0 * M_PI / np;
    double lum_area = 0.0;
    for (uint32_t i = 0; i < nt; i++) {
        double theta = (i + 0.5) * dtheta;
        double solid = (cos(i * dtheta) - cos((i + 1) * dtheta)) * dphi;
        for (uint32_t j = 0; j < np; j++) {
            double phi = (j + 0.5) * dphi;
            double dir[3] = {sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta)};
            double c[3] = {0.0, 0.0, 0.0};
            radiance(dir, c, user);
            float *cell = t->rgb + 3 * ((size_t)i * np + j);
            for (int k = 0; k < 3; k++) cell[k] = (float)c[k];
            double lum = cell_importance(cell);
            weight[(size_t)i * np + j] = lum;
            lum_area += lum * solid;
        }
    }
    double floor_lum = SKY_TABLE_FLOOR * lum_area / (4.0 * M_PI);

    /* Weight of a cell: (luminance + floor) times its solid angle, i.e. luminance times
     * sin(theta) integrated over the cell; 0 where the cell has no positive component. */
    double total = 0.0;
    for (uint32_t i = 0; i < nt; i++) {
        double solid = (cos(i * dtheta) - cos((i + 1) * dtheta)) * dphi;
        double sum = 0.0;
        for (uint32_t j = 0; j < np; j++) {
            size_t idx = (size_t)i * np + j;
            const float *cell = t->rgb + 3 * idx;
            int lit = (isfinite(cell[0]) && cell[0] > 0.0f) || (isfinite(cell[1]) && cell[1] > 0.0f) ||
                      (isfinite(cell[2]) && cell[2] > 0.0f);
            weight[idx] = lit ? (weight[idx] + floor_lum) * solid : 0.0;
            sum += weight[idx];
        }
        row_sum[i] = sum;
        total += sum;
    }

    /* CDFs in float with exact 0 and 1 ends; a row of zero weight gets a uniform conditional
     * CDF (never used: its row probability is 0). A sky without radiance leaves every CDF
     * entry at 0, which sampling reports as pdf 0. */
    double acc = 0.0;
    t->cdf_rows[0] = 0.0f;
    for (uint32_t i = 0; i < nt; i++) {
        acc += row_sum[i];
        t->cdf_rows[i + 1] = total > 0.0 ? (float)(acc / total) : 0.0f;
        float *cdf = t->cdf_cols + (size_t)i * (np + 1);
        double racc = 0.0;
        cdf[0] = 0.0f;
        for (uint32_t j = 0; j < np; j++) {
            racc += weight[(size_t)i * np + j];
            cdf[j + 1] = row_sum[i] > 0.0 ? (float)(racc / row_sum[i]) : (float)((j + 1.0) / np);
        }
        cdf[np] = 1.0f;
    }
    if (total > 0.0) t->cdf_rows[nt] = 1.0f;

    /* The pdf is the exact probability the float CDFs give a cell, over its solid angle. */
    for (uint32_t i = 0; i < nt; i++) {
        double solid = (cos(i * dtheta) - cos((i + 1) * dtheta)) * dphi;
        double p_row = (double)t->cdf_rows[i + 1] - (double)t->cdf_rows[i];
        const float *cdf = t->cdf_cols + (size_t)i * (np + 1);
        for (uint32_t j = 0; j < np; j++) {
            double p = p_row * ((double)cdf[j + 1] - (double)cdf[j]);
            t->pdf[(size_t)i * np + j] = (float)(p / solid);
        }
    }
    rc = 0;

done:
    free(weight);
    free(row_sum);
    if (rc) sky_table_free(t);
    return rc;
}

/* Index k in [0, n) with cdf[k] <= u < cdf[k+1], for cdf[0] <= u < cdf[n]. */
static uint32_t cdf_find(const float *cdf, uint32_t n, float u)
{
    uint32_t lo = 0, hi = n; /* cdf[lo] <= u, and u < cdf[hi] */
    while (hi - lo > 1) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (cdf[mid] <= u)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

float sky_table_sample(const sky_table *t, float u1, float u2, float dir[3], float rgb[3])
{
    const float below_one = 0x1.fffffep-1f;
    u1 = u1 > 0.0f ? (u1 < below_one ? u1 : below_one) : 0.0f;
    u2 = u2 > 0.0f ? (u2 < below_one ? u2 : below_one) : 0.0f;
    if (!(t->nt > 0 && t->cdf_rows[t->nt] > 0.0f)) {
        dir[0] = 0.0f;
        dir[1] = 0.0f;
        dir[2] = 1.0f;
        rgb[0] = rgb[1] = rgb[2] = 0.0f;
        return 0.0f;
    }
    uint32_t i = cdf_find(t->cdf_rows, t->nt, u1);
    const float *cdf = t->cdf_cols + (size_t)i * (t->np + 1);
    uint32_t j = cdf_find(cdf, t->np, u2);

    /* Position inside the cell, uniform in (cos theta, phi) between the edge margins. */
    double v1 = ((double)u1 - t->cdf_rows[i]) / ((double)t->cdf_rows[i + 1] - t->cdf_rows[i]);
    double v2 = ((double)u2 - cdf[j]) / ((double)cdf[j + 1] - cdf[j]);
    v1 = clampd(v1, 0.0, 1.0);
    v2 = clampd(v2, 0.0, 1.0);
    double dtheta = M_PI / t->nt, dphi = 2.0 * M_PI / t->np;
    double c0 = cos((i + SKY_TABLE_EDGE) * dtheta), c1 = cos((i + 1 - SKY_TABLE_EDGE) * dtheta);
    double cos_theta = c0 + v1 * (c1 - c0);
    double sin_theta = sqrt(fmax(0.0, 1.0 - cos_theta * cos_theta));
    double phi = (j + SKY_TABLE_EDGE + v2 * (1.0 - 2.0 * SKY_TABLE_EDGE)) * dphi;
    dir[0] = (float)(sin_theta * cos(phi));
    dir[1] = (float)(sin_theta * sin(phi));
    dir[2] = (float)cos_theta;

    size_t idx = (size_t)i * t->np + j;
    memcpy(rgb, t->rgb + 3 * idx, 3 * sizeof(float));
    return t->pdf[idx];
}

float sky_table_pdf(const sky_table *t, const float dir[3], float rgb[3])
{
    if (t->nt == 0 || t->np == 0) {
        rgb[0] = rgb[1] = rgb[2] = 0.0f;
        return 0.0f;
    }
    double x = dir[0], y = dir[1], z = dir[2];
    double theta = atan2(sqrt(x * x + y * y), z);
    double phi = atan2(y, x);
    if (phi < 0.0) phi += 2.0 * M_PI;
    double fi = theta / M_PI * t->nt, fj = phi / (2.0 * M_PI) * t->np;
    uint32_t i = fi > 0.0 ? (fi < t->nt - 1 ? (uint32_t)fi : t->nt - 1) : 0;
    uint32_t j = fj > 0.0 ? (fj < t->np - 1 ? (uint32_t)fj : t->np - 1) : 0;
    size_t idx = (size_t)i * t->np + j;
    memcpy(rgb, t->rgb + 3 * idx, 3 * sizeof(float));
    return t->pdf[idx];
}
