/* test_sky.c — the Preetham sky (zenith formulae, Perez normalisation, shape and colour, the
 * ground below the horizon, argument checks) and the sampling table (pdf normalisation,
 * agreement of sample and pdf, an unbiased estimate of sky irradiance). */
#include "harness.h"

#include "geometry/sky_preetham.h"
#include "render/sky_table.h"

#include <stdint.h>

#define DEG (M_PI / 180.0)

/* Unit direction at elevation elev above the horizon and azimuth phi from +X toward +Y. */
static void dir_from(double elev, double phi, double d[3])
{
    d[0] = cos(elev) * cos(phi);
    d[1] = cos(elev) * sin(phi);
    d[2] = sin(elev);
}

static double luminance(const double c[3]) { return 0.2126729 * c[0] + 0.7151522 * c[1] + 0.0721750 * c[2]; }

static void preetham_radiance_cb(const double dir[3], double rgb[3], const void *user)
{
    sky_preetham_radiance(user, dir, rgb);
}

static sky_preetham sky_at(double sun_elev, double sun_phi, double turbidity, double scale,
                           double albedo)
{
    sky_preetham s;
    double sun[3];
    dir_from(sun_elev, sun_phi, sun);
    int rc = sky_preetham_init(&s, sun, turbidity, scale, albedo);
    CHECK_INT(rc, 0);
    return s;
}

TEST(zenith_hand_values)
{
    double Yxy[3];
    /* T = 3, theta_s = 30 deg = 0.5235988 rad:
     *   chi = (4/9 - 3/120)(pi - pi/3) = 0.4194444 * 2.0943951 = 0.8784824, tan(chi) = 1.2059327
     *   Y_z = (4.0453*3 - 4.9710) * 1.2059327 - 0.2155*3 + 2.4192 = 7.1649 * 1.2059327 + 1.7727
     *       = 10.413087 kcd/m^2
     *   theta_s^2 = 0.2741557, theta_s^3 = 0.1435476
     *   x_z = 9 (0.00166 th^3 - 0.00375 th^2 + 0.00209 th)
     *       + 3 (-0.02903 th^3 + 0.06377 th^2 - 0.03202 th + 0.00394)
     *       + (0.11693 th^3 - 0.21196 th^2 + 0.06052 th + 0.25886) = 0.2534342
     *   y_z likewise with the y matrix = 0.2597925 */
    sky_preetham_zenith(3.0, 30.0 * DEG, Yxy);
    CHECK_NEAR(Yxy[0], 10.413087, 1e-5);
    CHECK_NEAR(Yxy[1], 0.2534342, 1e-6);
    CHECK_NEAR(Yxy[2], 0.2597925, 1e-6);
    /* T = 2, theta_s = 0: chi = (4/9 - 2/120) pi = 1.3439035, tan(chi) = 4.3314759,
     * Y_z = 3.1196 * 4.3314759 - 0.431 + 2.4192 = 15.500672. */
    sky_preetham_zenith(2.0, 0.0, Yxy);
    CHECK_NEAR(Yxy[0], 15.500672, 1e-5);
    /* Sun on the horizon: chi = 0, Y_z = -0.2155 T + 2.4192; below it, clamped to the same. */
    sky_preetham_zenith(4.0, M_PI / 2, Yxy);
    CHECK_NEAR(Yxy[0], 1.5572, 1e-9);
    double below[3];
    sky_preetham_zenith(4.0, M_PI / 2 + 0.3, below);
    CHECK_NEAR(below[0], Yxy[0], 1e-12);
    CHECK_NEAR(below[1], Yxy[1], 1e-12);
}

TEST(zenith_grows_with_turbidity)
{
    double prev = 0.0;
    for (double T = 2.0; T <= 10.0; T += 1.0) {
        double Yxy[3];
        sky_preetham_zenith(T, 10.0 * DEG, Yxy);
        CHECK(Yxy[0] > prev);
        prev = Yxy[0];
    }
}

TEST(zenith_direction_is_zenith_value)
{
    const double scale = 2.5;
    sky_preetham s = sky_at(60.0 * DEG, 0.7, 3.0, scale, 0.2);
    CHECK_NEAR(s.theta_s, 30.0 * DEG, 1e-12);
    CHECK_NEAR(sky_perez(s.perez_Y, 0.0, s.theta_s) / s.denom_Y, 1.0, 1e-15);
    const double up[3] = {0.0, 0.0, 1.0};
    double rgb[3];
    sky_preetham_radiance(&s, up, rgb);
    double want = 10.413087 / 100.0 * scale;
    CHECK_NEAR(luminance(rgb) / want, 1.0, 1e-3);
    /* Chromaticity of the returned colour is the zenith chromaticity. */
    double X = 0.4124564 * rgb[0] + 0.3575761 * rgb[1] + 0.1804375 * rgb[2];
    double Y = luminance(rgb);
    double Z = 0.0193339 * rgb[0] + 0.1191920 * rgb[1] + 0.9503041 * rgb[2];
    CHECK_NEAR(X / (X + Y + Z), 0.2534342, 1e-4);
    CHECK_NEAR(Y / (X + Y + Z), 0.2597925, 1e-4);
}

TEST(brightest_near_sun)
{
    const double sun_elev = 40.0 * DEG, sun_phi = 1.2;
    sky_preetham s = sky_at(sun_elev, sun_phi, 3.0, 1.0, 0.2);
    double near[3], anti[3], c_near[3], c_anti[3];
    dir_from(sun_elev + 5.0 * DEG, sun_phi, near);
    dir_from(sun_elev + 5.0 * DEG, sun_phi + M_PI, anti);
    sky_preetham_radiance(&s, near, c_near);
    sky_preetham_radiance(&s, anti, c_anti);
    CHECK(luminance(c_near) > 2.0 * luminance(c_anti));
}

TEST(circumsolar_symmetry)
{
    const double sun_elev = 35.0 * DEG, sun_phi = 30.0 * DEG;
    sky_preetham s = sky_at(sun_elev, sun_phi, 4.0, 1.0, 0.2);
    for (double off = 5.0; off < 180.0; off += 25.0) {
        double a[3], b[3], ca[3], cb[3];
        dir_from(20.0 * DEG, sun_phi + off * DEG, a);
        dir_from(20.0 * DEG, sun_phi - off * DEG, b);
        sky_preetham_radiance(&s, a, ca);
        sky_preetham_radiance(&s, b, cb);
        for (int k = 0; k < 3; k++) CHECK_NEAR(ca[k], cb[k], 1e-9 * (1.0 + fabs(ca[k])));
    }
    /* Not trivially symmetric: turning toward the sun changes the radiance. */
    double a[3], b[3], ca[3], cb[3];
    dir_from(20.0 * DEG, sun_phi + 10.0 * DEG, a);
    dir_from(20.0 * DEG, sun_phi + 100.0 * DEG, b);
    sky_preetham_radiance(&s, a, ca);
    sky_preetham_radiance(&s, b, cb);
    CHECK(luminance(ca) > 1.2 * luminance(cb));
}

TEST(clear_sky_is_blue)
{
    sky_preetham s = sky_at(70.0 * DEG, 0.0, 2.0, 1.0, 0.2);
    double d[3], c[3];
    dir_from(3.0 * DEG, M_PI, d); /* horizon opposite the sun */
    sky_preetham_radiance(&s, d, c);
    CHECK(c[2] > c[0]);
    dir_from(60.0 * DEG, M_PI, d);
    sky_preetham_radiance(&s, d, c);
    CHECK(c[2] > c[0]);
}

TEST(ground_below_horizon)
{
    sky_preetham a = sky_at(25.0 * DEG, 0.3, 3.0, 1.0, 0.3);
    sky_preetham b = sky_at(25.0 * DEG, 0.3, 3.0, 1.0, 0.6);
    sky_preetham black = sky_at(25.0 * DEG, 0.3, 3.0, 1.0, 0.0);
    double down[3], ca[3], cb[3], c0[3];
    dir_from(-30.0 * DEG, 2.0, down);
    sky_preetham_radiance(&a, down, ca);
    sky_preetham_radiance(&b, down, cb);
    sky_preetham_radiance(&black, down, c0);
    /* Horizon band 0..5 degrees: the ground / albedo lies within its extremes. */
    double lo = INFINITY, hi = 0.0;
    for (double e = 0.5; e < 5.0; e += 1.0)
        for (double p = 0.0; p < 360.0; p += 1.0) {
            double d[3], c[3];
            dir_from(e * DEG, p * DEG, d);
            sky_preetham_radiance(&a, d, c);
            lo = fmin(lo, luminance(c));
            hi = fmax(hi, luminance(c));
        }
    double g = luminance(ca) / 0.3;
    CHECK(g > lo && g < hi);
    for (int k = 0; k < 3; k++) {
        CHECK(ca[k] > 0.0);
        CHECK_NEAR(cb[k], 2.0 * ca[k], 1e-12);
        CHECK_NEAR(c0[k], 0.0, 0.0);
        CHECK_NEAR(ca[k], a.ground_rgb[k], 0.0);
    }
}

TEST(sun_below_horizon)
{
    sky_preetham s = sky_at(-10.0 * DEG, 0.5, 3.0, 1.0, 0.2);
    CHECK_NEAR(s.theta_s, M_PI / 2, 1e-12);
    CHECK_NEAR(s.sun_dir[2], 0.0, 0.0);
    CHECK_NEAR(atan2(s.sun_dir[1], s.sun_dir[0]), 0.5, 1e-12);
    for (double e = 0.0; e <= 90.0; e += 15.0) {
        double d[3], c[3];
        dir_from(e * DEG, 2.0, d);
        sky_preetham_radiance(&s, d, c);
        for (int k = 0; k < 3; k++) CHECK(isfinite(c[k]) && c[k] >= 0.0);
        CHECK(luminance(c) > 0.0);
    }
    /* A view exactly on the horizon stays finite. */
    double h[3] = {1.0, 0.0, 0.0}, c[3];
    sky_preetham_radiance(&s, h, c);
    CHECK(isfinite(c[0]) && isfinite(c[1]) && isfinite(c[2]));
}

TEST(init_rejects_bad_arguments)
{
    sky_preetham s;
    const double sun[3] = {0.0, 0.6, 0.8}, zero[3] = {0.0, 0.0, 0.0};
    CHECK_INT(sky_preetham_init(&s, sun, 1.0, 1.0, 0.2), -1);
    CHECK_INT(sky_preetham_init(&s, sun, 12.0, 1.0, 0.2), -1);
    CHECK_INT(sky_preetham_init(&s, sun, NAN, 1.0, 0.2), -1);
    CHECK_INT(sky_preetham_init(&s, zero, 3.0, 1.0, 0.2), -1);
    CHECK_INT(sky_preetham_init(&s, sun, 3.0, -1.0, 0.2), -1);
    CHECK_INT(sky_preetham_init(&s, sun, 3.0, 1.0, 1.5), -1);
    CHECK_INT(sky_preetham_init(&s, sun, 1.7, 1.0, 0.2), 0);
    CHECK_INT(sky_preetham_init(&s, sun, 10.0, 1.0, 0.2), 0);
    const double sun_long[3] = {0.0, 3.0, 4.0};
    CHECK_INT(sky_preetham_init(&s, sun_long, 3.0, 1.0, 0.2), 0);
    CHECK_NEAR(s.sun_dir[2], 0.8, 1e-15);
}

/* --- the table -------------------------------------------------------------------------- */

static int table_for(sky_table *t, const sky_preetham *s, uint32_t nt, uint32_t np)
{
    int rc = sky_table_build(t, nt, np, preetham_radiance_cb, s);
    CHECK_INT(rc, 0);
    return rc;
}

TEST(table_pdf_integrates_to_one)
{
    sky_preetham s = sky_at(30.0 * DEG, 2.0, 3.0, 1.0, 0.2);
    sky_table t;
    if (table_for(&t, &s, 64, 128)) return;
    /* Midpoint rule in (cos theta, phi), a grid not aligned with the table's cells. */
    const int nc = 700, nphi = 1300;
    double sum = 0.0;
    for (int a = 0; a < nc; a++) {
        double ct = 1.0 - 2.0 * (a + 0.5) / nc, st = sqrt(1.0 - ct * ct);
        for (int b = 0; b < nphi; b++) {
            double phi = 2.0 * M_PI * (b + 0.5) / nphi;
            float d[3] = {(float)(st * cos(phi)), (float)(st * sin(phi)), (float)ct}, c[3];
            sum += sky_table_pdf(&t, d, c, NULL);
        }
    }
    sum *= 4.0 * M_PI / ((double)nc * nphi);
    CHECK_NEAR(sum, 1.0, 0.01);
    sky_table_free(&t);
}

TEST(table_sample_matches_pdf)
{
    sky_preetham s = sky_at(15.0 * DEG, -1.0, 5.0, 1.0, 0.2);
    sky_table t;
    if (table_for(&t, &s, 32, 64)) return;
    const int n = 80;
    int mismatches = 0;
    for (int a = 0; a <= n; a++)
        for (int b = 0; b <= n; b++) {
            float u1 = a == n ? 0x1.fffffep-1f : (float)a / n;
            float u2 = b == n ? 0x1.fffffep-1f : (float)b / n;
            float d[3], c[3], c2[3];
            float pdf = sky_table_sample(&t, u1, u2, d, c);
            CHECK(pdf > 0.0f);
            CHECK_NEAR(sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), 1.0, 1e-6);
            float pdf2 = sky_table_pdf(&t, d, c2, NULL);
            if (fabsf(pdf2 - pdf) > 1e-4f * pdf || c[0] != c2[0] || c[1] != c2[1] || c[2] != c2[2])
                mismatches++;
        }
    CHECK_INT(mismatches, 0);
    sky_table_free(&t);
}

TEST(table_estimates_irradiance)
{
    sky_preetham s = sky_at(50.0 * DEG, 0.4, 2.5, 1.0, 0.2);
    /* Brute force: E = integral over the upper hemisphere of L cos(theta), midpoint rule in
     * (cos theta, phi). */
    const int nc = 800, nphi = 1600;
    double quad = 0.0;
    for (int a = 0; a < nc; a++) {
        double ct = (a + 0.5) / nc, st = sqrt(1.0 - ct * ct);
        for (int b = 0; b < nphi; b++) {
            double phi = 2.0 * M_PI * (b + 0.5) / nphi;
            double d[3] = {st * cos(phi), st * sin(phi), ct}, c[3];
            sky_preetham_radiance(&s, d, c);
            quad += luminance(c) * ct;
        }
    }
    quad *= 2.0 * M_PI / ((double)nc * nphi);

    sky_table t;
    if (table_for(&t, &s, 64, 128)) return;
    /* The base exactly (each row's base times the row's integral of cos theta, pi (cos^2
     * theta_0 - cos^2 theta_1)), plus Monte Carlo of the rest with table sampling over a
     * stratified 256 x 256 grid of (u1, u2). */
    double base = 0.0;
    for (uint32_t i = 0; i < t.nt / 2; i++) {
        double c0 = cos(i * M_PI / t.nt), c1 = cos((i + 1) * M_PI / t.nt);
        const float *b = t.base + 3 * i;
        base += (0.2126 * b[0] + 0.7152 * b[1] + 0.0722 * b[2]) * M_PI * (c0 * c0 - c1 * c1);
    }
    const int n = 256;
    double mc = 0.0;
    for (int a = 0; a < n; a++)
        for (int b = 0; b < n; b++) {
            float d[3], c[3], above[3], below[3];
            float pdf = sky_table_sample(&t, (a + 0.5f) / n, (b + 0.5f) / n, d, c);
            if (d[2] <= 0.0f || pdf <= 0.0f) continue;
            sky_table_pdf(&t, d, above, below);
            double dd[3] = {d[0], d[1], d[2]}, L[3];
            sky_preetham_radiance(&s, dd, L);
            for (int k = 0; k < 3; k++) L[k] -= below[k];
            mc += luminance(L) * d[2] / pdf;
        }
    mc /= (double)n * n;
    CHECK(quad > 0.0);
    fprintf(stderr, "  irradiance: base %.4f + sampled %.4f against %.4f\n", base, mc, quad);
    CHECK(base > 0.2 * quad); /* the base is a good part of the sky's light */
    CHECK_NEAR((base + mc) / quad, 1.0, 0.02);
    sky_table_free(&t);
}

/* A sky whose radiance depends on the elevation alone (a constant one among them) is all base:
 * next-event estimation has nothing to sample (pdf 0), and each row's base is its radiance. */
static void by_elevation(const double dir[3], double rgb[3], const void *user)
{
    (void)user;
    rgb[0] = 0.5 + dir[2], rgb[1] = 0.7, rgb[2] = 1.0;
}

TEST(table_of_a_sky_without_azimuthal_variation_is_base)
{
    sky_table t;
    CHECK_INT(sky_table_build(&t, 16, 32, by_elevation, NULL), 0);
    float d[3], c[3];
    CHECK_NEAR(sky_table_sample(&t, 0.3f, 0.6f, d, c), 0.0, 0.0);
    for (uint32_t i = 0; i < t.nt; i++) {
        const float *cell = t.rgb + 3 * i * t.np;
        for (int k = 0; k < 3; k++) CHECK_NEAR(t.base[3 * i + k], fmax(0.0, cell[k]), 0.0);
    }
    float up[3] = {0, 0, 1}, above[3], below[3];
    CHECK_NEAR(sky_table_pdf(&t, up, above, below), 0.0, 0.0);
    CHECK_NEAR(above[0] + above[1] + above[2], 0.0, 0.0);
    CHECK_NEAR(below[1], 0.7, 1e-6);
    CHECK_NEAR(t.irradiance_up + t.irradiance_down, 0.0, 0.0);
    sky_table_free(&t);
}

static void dim_with_bright_patch(const double dir[3], double rgb[3], const void *user)
{
    double v = dir[2] > 0.95 ? 1000.0 + 1000.0 * dir[0] : (dir[2] < -0.5 ? 0.0 : 1e-6 * (1.0 + dir[0]));
    rgb[0] = rgb[1] = rgb[2] = v;
}

TEST(table_floor_and_dark_cells)
{
    sky_table t;
    CHECK_INT(sky_table_build(&t, 32, 64, dim_with_bright_patch, NULL), 0);
    float mean_pdf = 1.0f / (4.0f * (float)M_PI);
    for (uint32_t i = 0; i < t.nt; i++)
        for (uint32_t j = 0; j < t.np; j++) {
            const float *c = t.rgb + 3 * (i * t.np + j);
            float p = t.pdf[i * t.np + j];
            if (c[0] > t.base[3 * i])
                CHECK(p > 1e-3f * mean_pdf); /* the floor: dim cells stay reachable */
            else
                CHECK_NEAR(p, 0.0, 0.0); /* nothing above the row's base, never sampled */
        }
    for (int a = 0; a < 64; a++) {
        float d[3], c[3];
        float pdf = sky_table_sample(&t, (a + 0.5f) / 64, 0.3f, d, c);
        CHECK(pdf > 0.0f && c[0] >= 0.0f && d[2] > -0.5f);
    }
    sky_table_free(&t);
}

static void black(const double dir[3], double rgb[3], const void *user)
{
    rgb[0] = rgb[1] = rgb[2] = 0.0;
}

TEST(table_black_and_bad_sizes)
{
    sky_table t;
    CHECK_INT(sky_table_build(&t, 8, 16, black, NULL), 0);
    float d[3], c[3];
    CHECK_NEAR(sky_table_sample(&t, 0.3f, 0.6f, d, c), 0.0, 0.0);
    CHECK_NEAR(d[2], 1.0, 0.0);
    CHECK_NEAR(sky_table_pdf(&t, d, c, NULL), 0.0, 0.0);
    sky_table_free(&t);
    CHECK(t.rgb == NULL && t.nt == 0);
    CHECK_INT(sky_table_build(&t, 0, 16, black, NULL), -1);
    CHECK(t.rgb == NULL && t.pdf == NULL);
    CHECK_INT(sky_table_build(&t, 8, 16, NULL, NULL), -1);
    CHECK_NEAR(sky_table_pdf(&t, d, c, NULL), 0.0, 0.0);
    sky_table_free(&t);
    sky_table_free(NULL);
}

TEST_LIST(TEST_CASE(zenith_hand_values), TEST_CASE(zenith_grows_with_turbidity),
          TEST_CASE(zenith_direction_is_zenith_value), TEST_CASE(brightest_near_sun),
          TEST_CASE(circumsolar_symmetry), TEST_CASE(clear_sky_is_blue),
          TEST_CASE(ground_below_horizon), TEST_CASE(sun_below_horizon),
          TEST_CASE(init_rejects_bad_arguments), TEST_CASE(table_pdf_integrates_to_one),
          TEST_CASE(table_sample_matches_pdf), TEST_CASE(table_estimates_irradiance),
          TEST_CASE(table_of_a_sky_without_azimuthal_variation_is_base),
          TEST_CASE(table_floor_and_dark_cells), TEST_CASE(table_black_and_bad_sizes))
