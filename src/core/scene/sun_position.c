/* sun_position.c — the sun's azimuth and elevation by Meeus's low-accuracy solar theory (the
 * NOAA solar calculator's algorithm). Equation numbers are those of "Astronomical Algorithms"
 * (2nd ed.); docs/models/sun_position.md gives the whole derivation and its deviations. */
#include "scene/sun_position.h"

#include <math.h>

#define DEG (M_PI / 180.0)

/* x reduced to [0, 360). */
static double wrap360(double x)
{
    x = fmod(x, 360.0);
    return x < 0.0 ? x + 360.0 : x;
}

sun_observer sun_observer_standard(double latitude_deg, double longitude_deg, double height_m)
{
    /* ICAO standard atmosphere, troposphere: p = p0 (1 - L h / T0)^(g M / (R L)) */
    double h = fmax(-500.0, fmin(height_m, 11000.0));
    return (sun_observer){.latitude_deg = latitude_deg,
                          .longitude_deg = longitude_deg,
                          .height_m = height_m,
                          .pressure_mbar = 1013.25 * pow(1.0 - 2.25577e-5 * h, 5.25588),
                          .temperature_c = 15.0 - 0.0065 * h};
}

double sun_julian_day(const sun_utc *t)
{
    /* Meeus 7.1 with the Gregorian correction B = 2 - A + A/4 */
    int y = t->year, m = t->month;
    if (m <= 2) y -= 1, m += 12;
    int a = (int)floor(y / 100.0);
    int b = 2 - a + (int)floor(a / 4.0);
    double day = t->day + (t->hour + (t->minute + t->second / 60.0) / 60.0) / 24.0;
    return floor(365.25 * (y + 4716)) + floor(30.6001 * (m + 1)) + day + b - 1524.5;
}

static int days_in_month(int year, int month)
{
    static const int days[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    int leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    return days[month - 1] + (month == 2 && leap);
}

static int check_input(const sun_utc *t, const sun_observer *o, err_buf *err)
{
    if (t->year < SUN_YEAR_MIN || t->year > SUN_YEAR_MAX)
        return err_fail(err, ERR_INPUT, "the year %d is outside %d..%d, where the solar position "
                        "algorithm's accuracy is stated", t->year, SUN_YEAR_MIN, SUN_YEAR_MAX);
    if (t->month < 1 || t->month > 12 || t->day < 1 || t->day > days_in_month(t->year, t->month))
        return err_fail(err, ERR_INPUT, "%04d-%02d-%02d is not a date in the calendar", t->year,
                        t->month, t->day);
    /* second 60 is a leap second */
    if (t->hour < 0 || t->hour > 23 || t->minute < 0 || t->minute > 59 || !(t->second >= 0.0) ||
        !(t->second < 61.0))
        return err_fail(err, ERR_INPUT, "%02d:%02d:%g is not a time of day (00:00:00 to 23:59:60)",
                        t->hour, t->minute, t->second);
    if (!(fabs(o->latitude_deg) <= 90.0) || !(fabs(o->longitude_deg) <= 180.0))
        return err_fail(err, ERR_INPUT, "latitude %g and longitude %g are not a place on the Earth "
                        "(latitude -90..90, longitude -180..180 degrees)", o->latitude_deg,
                        o->longitude_deg);
    if (!(o->pressure_mbar > 0.0 && o->pressure_mbar < 2000.0) ||
        !(o->temperature_c > -100.0 && o->temperature_c < 100.0))
        return err_fail(err, ERR_INPUT, "air at %g mbar and %g C is outside what refraction is "
                        "modelled for (0..2000 mbar, -100..100 C)", o->pressure_mbar,
                        o->temperature_c);
    return 0;
}

/* Saemundsson's refraction (Meeus 16.4) in degrees for a true elevation h (degrees), scaled
 * by pressure and temperature as Meeus (chapter 16) and SPA (equation 42) do. Below the
 * elevation where the sun's upper limb sets (-0.8333) no refraction is added. */
static double refraction(double h, double pressure_mbar, double temperature_c)
{
    if (h < -0.8333) return 0.0;
    double arcmin = 1.02 / tan((h + 10.3 / (h + 5.11)) * DEG);
    return arcmin / 60.0 * (pressure_mbar / 1010.0) * (283.0 / (273.0 + temperature_c));
}

int sun_position_at(const sun_utc *t, const sun_observer *o, sun_position *out, err_buf *err)
{
    if (check_input(t, o, err)) return -1;
    double jd = sun_julian_day(t);
    double T = (jd - 2451545.0) / 36525.0; /* 25.1; UT used for TT (see the model notes) */

    double L0 = wrap360(280.46646 + T * (36000.76983 + T * 0.0003032));  /* 25.2 */
    double M = wrap360(357.52911 + T * (35999.05029 - T * 0.0001537));   /* 25.3 */
    double e = 0.016708634 - T * (0.000042037 + T * 0.0000001267);      /* 25.4 */
    double C = (1.914602 - T * (0.004817 + T * 0.000014)) * sin(M * DEG) +
               (0.019993 - T * 0.000101) * sin(2.0 * M * DEG) + 0.000289 * sin(3.0 * M * DEG);
    double true_longitude = L0 + C, true_anomaly = M + C;
    double R = 1.000001018 * (1.0 - e * e) / (1.0 + e * cos(true_anomaly * DEG)); /* 25.5 */
    double omega = 125.04 - 1934.136 * T;
    double lambda = true_longitude - 0.00569 - 0.00478 * sin(omega * DEG); /* apparent */

    double eps0 = 23.0 + (26.0 + (21.448 - T * (46.8150 + T * (0.00059 - T * 0.001813))) / 60.0) / 60.0; /* 22.2 */
    double eps = eps0 + 0.00256 * cos(omega * DEG); /* 25.8 */
    double alpha = wrap360(atan2(cos(eps * DEG) * sin(lambda * DEG), cos(lambda * DEG)) / DEG); /* 25.6 */
    double delta = asin(sin(eps * DEG) * sin(lambda * DEG)) / DEG;                             /* 25.7 */

    /* Greenwich apparent sidereal time: mean (12.4) plus the equation of the equinoxes, with
     * the nutation in longitude to chapter 22's four terms (0.5" accuracy). */
    double theta0 = 280.46061837 + 360.98564736629 * (jd - 2451545.0) +
                    T * T * (0.000387933 - T / 38710000.0);
    double om = (125.04452 - 1934.136261 * T) * DEG;
    double Ls = (280.4665 + 36000.7698 * T) * DEG, Lm = (218.3165 + 481267.8813 * T) * DEG;
    double dpsi = (-17.20 * sin(om) - 1.32 * sin(2.0 * Ls) - 0.23 * sin(2.0 * Lm) +
                   0.21 * sin(2.0 * om)) / 3600.0;
    double theta = theta0 + dpsi * cos(eps * DEG);

    double H = wrap360(theta + o->longitude_deg - alpha); /* local hour angle, west positive */
    if (H > 180.0) H -= 360.0;
    double phi = o->latitude_deg * DEG, d = delta * DEG, h_rad = H * DEG;
    double sin_h = sin(phi) * sin(d) + cos(phi) * cos(d) * cos(h_rad); /* 13.6 */
    double h_geo = asin(fmax(-1.0, fmin(1.0, sin_h))) / DEG;
    /* 13.5: azimuth from the south, westward; +180 turns it to clockwise from north */
    double az = atan2(sin(h_rad), cos(h_rad) * sin(phi) - tan(d) * cos(phi)) / DEG + 180.0;

    /* The sun's equatorial horizontal parallax (8.794" at 1 au) lowers it by pi cos h, the
     * first-order term of Meeus chapter 40 (at most 0.0025 degree). */
    double parallax = 8.794 / 3600.0 / R;
    double h_true = h_geo - parallax * cos(h_geo * DEG);
    double h_app = h_true + refraction(h_true, o->pressure_mbar, o->temperature_c);

    *out = (sun_position){.azimuth_deg = wrap360(az),
                          .elevation_deg = h_app,
                          .zenith_deg = 90.0 - h_app,
                          .elevation_true_deg = h_true,
                          .right_ascension_deg = alpha,
                          .declination_deg = delta,
                          .hour_angle_deg = H,
                          .distance_au = R,
                          .julian_day = jd};
    return 0;
}
