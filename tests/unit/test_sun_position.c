/* test_sun_position.c — the solar position against published values: the worked example of
 * NREL's SPA paper (Reda & Andreas 2004), Meeus's example 25.a, the 2026 equinox and solstices
 * (instants from the US Naval Observatory), the polar night, refraction, and the refusal of
 * dates and places that are not valid. */
#include "harness.h"

#include "season/sun_position.h"

static sun_position at(int y, int mo, int d, int h, int mi, double s, sun_observer o)
{
    sun_utc t = {y, mo, d, h, mi, s};
    sun_position p = {0};
    err_buf err = {{0}};
    int rc = sun_position_at(&t, &o, &p, &err);
    CHECK_INT(rc, 0);
    if (rc) fprintf(stderr, "%s\n", err.msg);
    return p;
}

/* SPA paper, table A4.1: 2003-10-17 12:30:30 local time at UTC-7 (19:30:30 UTC), Golden,
 * Colorado; topocentric zenith 50.11162 and azimuth 194.34024 degrees. The theory here is
 * stated to 0.01 degree. */
TEST(spa_example)
{
    sun_observer o = {.latitude_deg = 39.742476, .longitude_deg = -105.1786,
                      .height_m = 1830.14, .pressure_mbar = 820.0, .temperature_c = 11.0};
    sun_position p = at(2003, 10, 17, 19, 30, 30.0, o);
    CHECK_NEAR(p.zenith_deg, 50.11162, 0.01);
    CHECK_NEAR(p.azimuth_deg, 194.34024, 0.01);
    fprintf(stderr, "SPA example: zenith %.5f (SPA 50.11162), azimuth %.5f (SPA 194.34024)\n",
            p.zenith_deg, p.azimuth_deg);
    /* the paper's geocentric declination and right ascension */
    CHECK_NEAR(p.declination_deg, -9.31434, 0.01);
    CHECK_NEAR(p.right_ascension_deg, 202.22741, 0.01);
}

/* Meeus, Astronomical Algorithms, example 25.a: 1992 October 13 0h; the same theory, so the
 * apparent right ascension, declination and distance agree to the example's digits. */
TEST(meeus_example_25a)
{
    sun_position p = at(1992, 10, 13, 0, 0, 0.0, sun_observer_standard(0, 0, 0));
    CHECK_NEAR(p.julian_day, 2448908.5, 1e-9);
    CHECK_NEAR(p.right_ascension_deg, 198.38083, 0.0002);
    CHECK_NEAR(p.declination_deg, -7.78507, 0.0002);
    CHECK_NEAR(p.distance_au, 0.99766, 0.00001);
}

/* March equinox 2026-03-20 14:46 UT (USNO): the declination is zero; at the equator the sun
 * stands overhead where the local apparent noon falls: 14:46 UT is 41.5 degrees of hour angle
 * past Greenwich noon, and the equation of time that day (-7.5 minutes: the true sun runs late)
 * moves the noon 1.9 degrees back east, to 39.63 W. */
TEST(equinox_noon_at_equator)
{
    sun_position p = at(2026, 3, 20, 14, 46, 0.0, sun_observer_standard(0.0, -39.63, 0.0));
    CHECK_NEAR(p.declination_deg, 0.0, 0.005);
    CHECK(p.elevation_deg > 89.9);
    /* an hour of hour angle away the sun stands 15 degrees lower, in the east */
    sun_position q = at(2026, 3, 20, 14, 46, 0.0, sun_observer_standard(0.0, -24.63, 0.0));
    CHECK_NEAR(q.elevation_true_deg, 75.0, 0.1);
    CHECK_NEAR(q.azimuth_deg, 270.0, 0.1);
    sun_position r = at(2026, 3, 20, 14, 46, 0.0, sun_observer_standard(0.0, -54.63, 0.0));
    CHECK_NEAR(r.azimuth_deg, 90.0, 0.1);
}

/* June solstice 2026-06-21 08:24 UT and December solstice 2026-12-21 20:50 UT (USNO): the
 * declination is +/- the obliquity (23.436 degrees in 2026). */
TEST(solstices)
{
    sun_position june = at(2026, 6, 21, 8, 24, 0.0, sun_observer_standard(51.5, 0.0, 0.0));
    CHECK_NEAR(june.declination_deg, 23.436, 0.005);
    sun_position dec = at(2026, 12, 21, 20, 50, 0.0, sun_observer_standard(51.5, 0.0, 0.0));
    CHECK_NEAR(dec.declination_deg, -23.436, 0.005);
}

/* Polar night: at the North Pole on the December solstice the sun circles 23.4 degrees below
 * the horizon whatever the hour; at Tromso (69.65 N) it stays below the horizon at noon. */
TEST(polar_night)
{
    for (int hour = 0; hour < 24; hour += 6) {
        sun_position p = at(2026, 12, 21, hour, 0, 0.0, sun_observer_standard(90.0, 0.0, 0.0));
        CHECK_NEAR(p.elevation_deg, -23.436, 0.01);
        CHECK_NEAR(p.elevation_deg, p.elevation_true_deg, 1e-12); /* no refraction below */
    }
    sun_position noon = at(2026, 12, 21, 10, 45, 0.0, sun_observer_standard(69.65, 18.96, 0.0));
    CHECK(noon.elevation_deg < -2.5);
    CHECK_NEAR(noon.azimuth_deg, 180.0, 1.0);
    /* and the midnight sun at the June solstice */
    sun_position midnight = at(2026, 6, 21, 22, 45, 0.0, sun_observer_standard(69.65, 18.96, 0.0));
    CHECK(midnight.elevation_deg > 2.5);
    CHECK(midnight.azimuth_deg > 359.0 || midnight.azimuth_deg < 1.0);
}

/* Refraction lifts the sun by about 34' at the horizon and 1' at 45 degrees (Meeus ch. 16), and
 * less in thin, warm air. */
TEST(refraction)
{
    sun_observer sea = {.latitude_deg = 0, .longitude_deg = -39.63, .pressure_mbar = 1010,
                        .temperature_c = 10};
    /* equinox evening at the equator: the sun near the horizon in the west */
    sun_position p = at(2026, 3, 20, 20, 46, 0.0, sea);
    double lift = p.elevation_deg - p.elevation_true_deg;
    CHECK(p.elevation_true_deg > -0.8 && p.elevation_true_deg < 0.8);
    CHECK(lift > 0.35 && lift < 0.6);
    sun_observer high = sea;
    high.pressure_mbar = 700, high.temperature_c = 30;
    sun_position q = at(2026, 3, 20, 20, 46, 0.0, high);
    CHECK_NEAR(q.elevation_deg - q.elevation_true_deg, lift * 700.0 / 1010.0 * 283.0 / 303.0, 1e-3);
    sun_position r = at(2026, 3, 20, 17, 46, 0.0, sea); /* 45 degrees up */
    CHECK_NEAR(r.elevation_deg - r.elevation_true_deg, 1.0 / 60.0, 0.002);
}

TEST(standard_atmosphere)
{
    sun_observer o = sun_observer_standard(10, 20, 1830.14);
    CHECK_NEAR(o.pressure_mbar, 812.0, 0.5); /* ICAO table: 815.0 at 1800 m, 795.0 at 2000 m */
    CHECK_NEAR(o.temperature_c, 3.1, 0.05);
    CHECK_NEAR(sun_observer_standard(0, 0, 0).pressure_mbar, 1013.25, 1e-9);
}

TEST(refuses_bad_input)
{
    sun_observer o = sun_observer_standard(10, 20, 0);
    sun_position p;
    err_buf err = {{0}};
    sun_utc feb30 = {2026, 2, 30, 12, 0, 0};
    CHECK_INT(sun_position_at(&feb30, &o, &p, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "2026-02-30 is not a date");
    sun_utc feb29 = {2024, 2, 29, 12, 0, 0};
    CHECK_INT(sun_position_at(&feb29, &o, &p, &err), 0);
    sun_utc old = {1850, 6, 1, 12, 0, 0};
    CHECK_INT(sun_position_at(&old, &o, &p, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "outside 1900..2100");
    sun_utc late = {2026, 6, 1, 24, 0, 0};
    CHECK_INT(sun_position_at(&late, &o, &p, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "not a time of day");
    sun_utc ok = {2026, 6, 1, 12, 0, 0};
    o.latitude_deg = 91;
    CHECK_INT(sun_position_at(&ok, &o, &p, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "latitude -90..90");
}

TEST_LIST(TEST_CASE(spa_example), TEST_CASE(meeus_example_25a), TEST_CASE(equinox_noon_at_equator),
          TEST_CASE(solstices), TEST_CASE(polar_night), TEST_CASE(refraction),
          TEST_CASE(standard_atmosphere), TEST_CASE(refuses_bad_input))
