/* test_atmosphere.c — the physical sky's model (geometry/atmosphere.h): Koschmieder's
 * extinction at the camera, a segment's transmittance against the analytic optical depth of an
 * exponential atmosphere, a blue zenith over a paler horizon, the reddening of the sun and of
 * the sky around it as the sun sets, no light from an atmosphere of zero density, and the
 * argument checks, and the tables the same whatever the thread count. */
#include "harness.h"

#include <string.h>

#include "geometry/atmosphere.h"

#define DEG (M_PI / 180.0)

/* Bruneton and Neyret's sea-level Rayleigh coefficients and the scale heights (the model's). */
static const double BETA_R[3] = {5.8e-6, 13.5e-6, 33.1e-6};
#define HR 8000.0
#define HM 1200.0

static atmosphere atmo; /* ~60 KB: static rather than on the stack */

static void sun_at(double elev_deg, double azimuth_deg, double d[3])
{
    double e = elev_deg * DEG, a = azimuth_deg * DEG;
    d[0] = cos(e) * sin(a);
    d[1] = cos(e) * cos(a);
    d[2] = sin(e);
}

static void setup(double elev_deg, double altitude, double visibility_km, double density)
{
    double sun[3], e[3] = {1, 1, 1};
    sun_at(elev_deg, 180, sun);
    CHECK_INT(atmosphere_init(&atmo, sun, e, altitude, visibility_km, density, 1, 0.2, 0), 0);
}

TEST(koschmieder_extinction_at_the_camera)
{
    const double V[3] = {10, 30, 100}, alt[3] = {0, 150, 1500};
    for (int i = 0; i < 3; i++) {
        setup(40, alt[i], V[i], 1);
        CHECK_NEAR(atmosphere_extinction_550(&atmo, alt[i]) * V[i] * 1000.0, 3.912, 1e-9);
        /* a horizontal segment at the camera's altitude: exactly exp(-3.912 d / V) at 550 nm */
        double d[3] = {0, 1, 0}, t[3], s[3];
        atmosphere_segment(&atmo, alt[i], d, 5000, t, s);
        CHECK_NEAR(t[1], exp(-3.912 * 5.0 / V[i]), 1e-9);
    }
    /* the haze alone: Mie extinction falls with its scale height, Rayleigh with its own */
    setup(40, 150, 30, 1);
    double mie_150 = 3.912 / 30000.0 - BETA_R[1] * exp(-150 / HR);
    CHECK_NEAR(atmo.beta_mie_ext, mie_150 * exp(150 / HM), 1e-12);
}

TEST(segment_transmittance_is_the_analytic_optical_depth)
{
    setup(40, 150, 25, 1);
    /* a line of sight climbing 1.2 km over 12 km from 150 m: for a density exp(-h / H) along
     * h = h0 + t dz the optical depth is beta H / dz (e^(-h0/H) - e^(-(h0 + L dz)/H)) */
    double len = 12000, d[3] = {0, sqrt(1 - 0.01), 0.1}, t[3], s[3];
    atmosphere_segment(&atmo, 150, d, len, t, s);
    for (int k = 0; k < 3; k++) {
        double dz = d[2], h1 = 150 + len * dz;
        double tau = BETA_R[k] * HR / dz * (exp(-150 / HR) - exp(-h1 / HR)) +
                     atmo.beta_mie_ext * HM / dz * (exp(-150 / HM) - exp(-h1 / HM));
        CHECK_NEAR(-log(t[k]) / tau, 1.0, 2e-3); /* 16 midpoint steps */
    }
    /* in-scattered light is positive, bluest where Rayleigh dominates */
    CHECK(s[0] > 0 && s[2] > s[0]);
}

static double blue_over_red(const double c[3]) { return c[2] / c[0]; }

TEST(zenith_bluer_than_horizon)
{
    setup(40, 100, 30, 1);
    double zen[3], hor[3], up[3] = {0, 0, 1}, side[3];
    sun_at(1, 90, side); /* 90 degrees from the sun, just above the horizon */
    atmosphere_sky(&atmo, up, zen);
    atmosphere_sky(&atmo, side, hor);
    CHECK(blue_over_red(zen) > 1.3 * blue_over_red(hor));
    CHECK(zen[2] > zen[1] && zen[1] > zen[0]);
    /* the hazy horizon is brighter than the zenith (green channel) */
    CHECK(hor[1] > zen[1]);
}

TEST(sunset_reddens_sun_and_sky)
{
    double t_high[3], t_low[3], sky_high[3], sky_low[3];
    double v_high[3], v_low[3];
    setup(45, 100, 30, 1);
    atmosphere_sun_transmittance(&atmo, 100, t_high);
    sun_at(40, 180, v_high); /* 5 degrees under the sun */
    atmosphere_sky(&atmo, v_high, sky_high);
    for (int k = 0; k < 3; k++) sky_high[k] /= atmo.sun_top[k]; /* per unit sun above the air */
    setup(2, 100, 30, 1);
    atmosphere_sun_transmittance(&atmo, 100, t_low);
    sun_at(2, 170, v_low); /* 10 degrees beside the low sun, at its height */
    atmosphere_sky(&atmo, v_low, sky_low);
    for (int k = 0; k < 3; k++) sky_low[k] /= atmo.sun_top[k];
    /* the direct sun: all channels dimmer, blue far more than red */
    for (int k = 0; k < 3; k++) CHECK(t_low[k] < t_high[k]);
    CHECK(t_low[0] / t_low[2] > 3.0 * (t_high[0] / t_high[2]));
    /* the sky around the sun turns from white-blue to red-orange */
    CHECK(sky_low[0] / sky_low[2] > 2.0 * (sky_high[0] / sky_high[2]));
    CHECK(sky_low[0] > sky_low[2]);
}

TEST(zero_density_scatters_nothing)
{
    setup(30, 100, 30, 0);
    double c[3], d[3];
    for (int i = 0; i < 8; i++) {
        sun_at(5 + 10 * i, 45 * i, d);
        atmosphere_sky(&atmo, d, c);
        CHECK(c[0] == 0 && c[1] == 0 && c[2] == 0);
        double t[3], s[3];
        atmosphere_segment(&atmo, 100, d, 1e5, t, s);
        for (int k = 0; k < 3; k++) CHECK(t[k] == 1.0 && s[k] == 0.0);
    }
    /* the sun above the air is the sun at the ground */
    for (int k = 0; k < 3; k++) CHECK(atmo.sun_top[k] == 1.0);
}

TEST(argument_checks)
{
    double sun[3] = {0, 0, 1}, zero[3] = {0, 0, 0}, e[3] = {1, 1, 1};
    CHECK_INT(atmosphere_init(&atmo, zero, e, 0, 30, 1, 1, 0.2, 0), -1);
    CHECK_INT(atmosphere_init(&atmo, sun, e, 0, 0, 1, 1, 0.2, 0), -1);
    CHECK_INT(atmosphere_init(&atmo, sun, e, 0, 30, -1, 1, 0.2, 0), -1);
    CHECK_INT(atmosphere_init(&atmo, sun, e, 0, 30, 1, 1, 1.5, 0), -1);
    /* clean air at sea level limits the range to 3.912 / 13.5e-6 m = 290 km */
    CHECK_NEAR(atmosphere_clear_visibility_km(0), 289.78, 0.01);
    CHECK_INT(atmosphere_init(&atmo, sun, e, 0, 300, 1, 1, 0.2, 0), -1);
    CHECK_INT(atmosphere_init(&atmo, sun, e, 3000, 300, 1, 1, 0.2, 0), 0); /* thinner air up there */
}

/* The tables built on one thread and on three are the same to the bit. */
TEST(tables_whatever_the_threads)
{
    static atmosphere one, three; /* large: not on the stack */
    double sun[3], e[3] = {1, 0.95, 0.9};
    sun_at(25, 120, sun);
    CHECK_INT(atmosphere_init(&one, sun, e, 240, 30, 1, 1, 0.2, 1), 0);
    CHECK_INT(atmosphere_init(&three, sun, e, 240, 30, 1, 1, 0.2, 3), 0);
    CHECK(!memcmp(&one, &three, sizeof one));
    CHECK(one.view[64][10][1] > 0.0f && one.multiple[5][20][2] > 0.0f);
}

TEST_LIST(TEST_CASE(koschmieder_extinction_at_the_camera), TEST_CASE(segment_transmittance_is_the_analytic_optical_depth),
          TEST_CASE(zenith_bluer_than_horizon), TEST_CASE(sunset_reddens_sun_and_sky),
          TEST_CASE(zero_density_scatters_nothing), TEST_CASE(argument_checks),
          TEST_CASE(tables_whatever_the_threads))
