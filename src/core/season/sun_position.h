/* sun_position.h — where the sun stands in the sky of a place at an instant: azimuth (clockwise
 * from north) and elevation (with atmospheric refraction), from a UTC date and time and the
 * observer's longitude, latitude and height.
 *
 * The algorithm is the NOAA solar calculator's, which is the low-accuracy solar theory of
 * J. Meeus, "Astronomical Algorithms" (2nd ed., 1998), chapter 25 (equations 25.2-25.8) with
 * the obliquity of chapter 22 (22.2), the sidereal time of chapter 12 (12.4), the horizontal
 * coordinates of chapter 13 (13.5, 13.6), the sun's parallax (chapter 40, to first order) and
 * Saemundsson's refraction (16.4) scaled by pressure and temperature. Meeus states the sun's
 * apparent longitude to about 0.01 degree; azimuth and elevation here agree with NREL's SPA
 * (Reda & Andreas 2004) to about 0.01 degree between 1900 and 2100. docs/models/sun_position.md
 * lists every equation and every deviation.
 *
 * Pure functions: no allocation, no state. */
#ifndef SYLVA_SUN_POSITION_H
#define SYLVA_SUN_POSITION_H

#include <stdint.h>

#include "util/err.h"

/* An instant in UTC, proleptic Gregorian calendar. second may hold a fraction. */
typedef struct sun_utc {
    int year, month, day, hour, minute;
    double second;
} sun_utc;

/* Where the sun is seen from, and the air it is seen through. */
typedef struct sun_observer {
    double latitude_deg;   /* -90..90, north positive */
    double longitude_deg;  /* -180..180, east positive */
    double height_m;       /* above sea level; sets the default pressure */
    double pressure_mbar;  /* air pressure at the observer (refraction); > 0 */
    double temperature_c;  /* air temperature at the observer (refraction); > -273.15 */
} sun_observer;

typedef struct sun_position {
    double azimuth_deg;        /* clockwise from north, [0, 360) */
    double elevation_deg;      /* topocentric, refraction included */
    double zenith_deg;         /* 90 - elevation_deg */
    double elevation_true_deg; /* topocentric, without refraction */
    double right_ascension_deg;/* apparent, geocentric, [0, 360) */
    double declination_deg;    /* apparent, geocentric */
    double hour_angle_deg;     /* local, geocentric, (-180, 180], west positive */
    double distance_au;        /* Earth-sun distance */
    double julian_day;         /* of the instant, UT */
} sun_position;

/* The first and last years computed (the theory's accuracy is stated for 1900-2100). */
#define SUN_YEAR_MIN 1900
#define SUN_YEAR_MAX 2100

/* An observer at (latitude, longitude, height) in the ICAO standard atmosphere: pressure
 * 1013.25 mbar at sea level falling with height, temperature 15 C falling 6.5 K per km. */
sun_observer sun_observer_standard(double latitude_deg, double longitude_deg, double height_m);

/* Reads an ISO 8601 date and time with its UTC offset, "2026-06-21T14:30:00+01:00",
 * "2026-06-21T13:30Z" or "2026-06-21T14:30:00.5+0100" (seconds and their fraction optional, the
 * offset required: a local time without one names no instant), into the UTC instant *out.
 * Returns 0, or -1 with err set to what is wrong (the caller adds where and an example). */
int sun_utc_parse(const char *text, sun_utc *out, err_buf *err);

/* The Julian day of a UTC instant (Meeus 7.1, Gregorian calendar). */
double sun_julian_day(const sun_utc *t);

/* The sun's position for observer o at instant t. Returns 0, or -1 with err set when the
 * instant is not a valid date and time between SUN_YEAR_MIN and SUN_YEAR_MAX, or the observer
 * is out of range. */
int sun_position_at(const sun_utc *t, const sun_observer *o, sun_position *out, err_buf *err);

#endif
