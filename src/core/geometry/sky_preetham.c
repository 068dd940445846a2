/* sky_preetham.c — the Preetham, Shirley and Smits (1999) daylight sky. Owns the model's
 * coefficients, its clamps (sun and view directions at the horizon) and the ground colour below
 * the horizon. It knows nothing of the sun disc itself: that is a separate light.
 * See docs/models/sky.md for the equations.
 */
#include "geometry/sky_preetham.h"

#include <float.h>
#include <math.h>
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
