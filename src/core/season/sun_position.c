/* sun_position.c — the sun's azimuth and elevation by Meeus's low-accuracy solar theory (the
 * NOAA solar calculator's algorithm). Equation numbers are those of "Astronomical Algorithms"
 * (2nd ed.); docs/models/sun_position.md gives the whole derivation and its deviations. */
#include "season/sun_position.h"

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

/* Days since 1970-01-01 of a proleptic Gregorian date, and back (the era-based algorithm of
 * H. Hinnant's "chrono-compatible low-level date algorithms"). */
static int64_t days_from_civil(int64_t y, int m, int d)
{
    y -= m <= 2;
    int64_t era = (y >= 0 ? y : y - 399) / 400;
    int64_t yoe = y - era * 400;
    int64_t doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
    int64_t doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + doe - 719468;
}

static void civil_from_days(int64_t z, int *y, int *m, int *d)
{
    z += 719468;
    int64_t era = (z >= 0 ? z : z - 146096) / 146097;
    int64_t doe = z - era * 146097;
    int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    int64_t mp = (5 * doy + 2) / 153;
    *d = (int)(doy - (153 * mp + 2) / 5 + 1);
    *m = (int)(mp < 10 ? mp + 3 : mp - 9);
    *y = (int)(yoe + era * 400 + (*m <= 2));
}

/* n decimal digits at *s into *v, advancing *s; 0 when they are not all digits. */
static int digits(const char **s, int n, int *v)
{
    *v = 0;
    for (int i = 0; i < n; i++, (*s)++) {
        if (**s < '0' || **s > '9') return 0;
        *v = *v * 10 + (**s - '0');
    }
    return 1;
}

int sun_utc_parse(const char *text, sun_utc *out, err_buf *err)
{
    const char *s = text;
    sun_utc t = {0};
    if (!digits(&s, 4, &t.year) || *s++ != '-' || !digits(&s, 2, &t.month) || *s++ != '-' ||
        !digits(&s, 2, &t.day))
        return err_fail(err, ERR_INPUT, "'%s' does not begin with a date YYYY-MM-DD", text);
    if (*s != 'T')
        return err_fail(err, ERR_INPUT, "'%s' has no time: the date is followed by T and the time "
                        "hh:mm:ss", text);
    s++;
    if (!digits(&s, 2, &t.hour) || *s++ != ':' || !digits(&s, 2, &t.minute))
        return err_fail(err, ERR_INPUT, "'%s' has no time hh:mm[:ss] after the T", text);
    if (*s == ':') {
        s++;
        int sec;
        if (!digits(&s, 2, &sec))
            return err_fail(err, ERR_INPUT, "'%s': the seconds are two digits", text);
        t.second = sec;
        if (*s == '.' || *s == ',') {
            s++;
            double scale = 0.1;
            if (*s < '0' || *s > '9')
                return err_fail(err, ERR_INPUT, "'%s': a decimal point with no digits", text);
            for (; *s >= '0' && *s <= '9'; s++, scale *= 0.1) t.second += (*s - '0') * scale;
        }
    }
    int offset_min = 0;
    if (*s == 'Z') {
        s++;
    } else if (*s == '+' || *s == '-') {
        int sign = *s++ == '-' ? -1 : 1, oh, om = 0, ok = digits(&s, 2, &oh);
        if (ok && *s == ':') s++;
        if (ok && *s) ok = digits(&s, 2, &om); /* "+01" alone is a whole-hour offset */
        if (!ok || oh > 14 || om > 59)
            return err_fail(err, ERR_INPUT, "'%s': the UTC offset is +hh:mm or -hh:mm, at most 14 "
                            "hours", text);
        offset_min = sign * (oh * 60 + om);
    } else {
        return err_fail(err, ERR_INPUT, "'%s' gives no UTC offset: end it with Z (UTC) or +hh:mm / "
                        "-hh:mm, the local time's offset from UTC", text);
    }
    if (*s)
        return err_fail(err, ERR_INPUT, "'%s' goes on after the date and time ('%s')", text, s);
    if (t.month < 1 || t.month > 12 || t.day < 1 || t.day > days_in_month(t.year, t.month))
        return err_fail(err, ERR_INPUT, "'%s': %04d-%02d-%02d is not a date in the calendar", text,
                        t.year, t.month, t.day);
    if (t.hour > 23 || t.minute > 59 || t.second >= 61.0)
        return err_fail(err, ERR_INPUT, "'%s': %02d:%02d is not a time of day", text, t.hour,
                        t.minute);
    /* local time less the offset, with the day carried */
    int64_t minutes = days_from_civil(t.year, t.month, t.day) * 1440 + t.hour * 60 + t.minute -
                      offset_min;
    int64_t day = minutes >= 0 ? minutes / 1440 : -((-minutes + 1439) / 1440);
    int64_t in_day = minutes - day * 1440;
    civil_from_days(day, &t.year, &t.month, &t.day);
    t.hour = (int)(in_day / 60), t.minute = (int)(in_day % 60);
    *out = t;
    return 0;
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
