/* test_eco_factors.c — the terrain factors on synthetic terrains with known answers: a flat
 * plane, a ridge, a valley with water; the humidity runoff, shelter angle and sun path by hand. */
#include "eco_fixture.h"
#include "eco_terrain.h"

static double flat(double x, double y) { return 5.0; }
/* An east-west ridge along y = 0, 20 m high, flanks 100 m wide. */
static double ridge_ew(double x, double y) { return 20.0 * fmax(0.0, 1.0 - fabs(y) / 100.0); }
/* A north-south ridge along x = 0. */
static double ridge_ns(double x, double y) { return 20.0 * fmax(0.0, 1.0 - fabs(x) / 100.0); }
/* A north-south V valley along x = 0, rising 0.3 m per metre to either side. */
static double valley(double x, double y) { return 0.3 * fabs(x); }

static eco_terrain build(eco_height_fn z, eco_factor_params fp)
{
    sylva_heightfield hf = fixture_heightfield(41, 41, -200, -200, 10, z);
    eco_terrain t;
    char msg[256] = "";
    int rc = eco_terrain_build(&t, &hf, &fp, msg, sizeof msg);
    CHECK_INT(rc, 0);
    free(hf.z);
    return t;
}

static float at(const eco_terrain *t, eco_factor f, double x, double y)
{
    int64_t p = eco_patch_of(t, x, y);
    return p < 0 ? -1.0f : t->factor[f][p];
}

TEST(flat_plane)
{
    eco_terrain t = build(flat, fixture_factor_params(40));
    CHECK_INT(t.ni, 40);
    CHECK_INT(t.nk, 40);
    CHECK_NEAR(t.kx, 10.0, 1e-12);
    /* the expected sunniness: every sample lights the plane with the sine of its elevation */
    double sum = 0, wsum = 0;
    for (uint32_t n = 0; n < 9; n++) {
        double d[3], w;
        eco_sun_sample(46, 9, n, d, &w);
        sum += w * (d[2] > 0 ? d[2] : 0.2), wsum += w;
    }
    for (size_t p = 0; p < (size_t)t.ni * t.nk; p++) {
        CHECK_NEAR(t.factor[ECO_SLOPE][p], 0.0, 1e-7);
        CHECK_NEAR(t.factor[ECO_WINDINESS][p], 1.0, 0);
        CHECK_NEAR(t.factor[ECO_SUNNINESS][p], sum / wsum, 1e-6);
        CHECK_NEAR(t.factor[ECO_ALTITUDE][p], 0.5, 0); /* no spread: the middle */
        CHECK_NEAR(t.factor[ECO_HUMIDITY][p], 0.5, 0);
        CHECK_INT(t.water[p], 0);
    }
    eco_terrain_free(&t);
}

TEST(ridge_south_face_sunnier_and_slopes)
{
    eco_terrain t = build(ridge_ew, fixture_factor_params(40));
    float south = at(&t, ECO_SUNNINESS, 0, -50), north = at(&t, ECO_SUNNINESS, 0, 50);
    float plain = at(&t, ECO_SUNNINESS, 0, -150);
    CHECK(south > plain + 0.02f);
    CHECK(north < plain - 0.02f);
    /* both faces have the same slope: 1 - cos(atan(0.2)) */
    double s = 1.0 - 1.0 / sqrt(1.0 + 0.04);
    CHECK_NEAR(at(&t, ECO_SLOPE, 0, -50), s, 1e-6);
    CHECK_NEAR(at(&t, ECO_SLOPE, 0, 50), s, 1e-6);
    CHECK_NEAR(at(&t, ECO_ALTITUDE, 0, -5), 1.0, 0.06);
    CHECK_NEAR(at(&t, ECO_ALTITUDE, 0, -195), 0.0, 1e-6);
    eco_terrain_free(&t);
}

TEST(ridge_sun_mirrors_south_of_the_equator)
{
    eco_factor_params fp = fixture_factor_params(40);
    fp.latitude_deg = -46;
    eco_terrain t = build(ridge_ew, fp);
    CHECK(at(&t, ECO_SUNNINESS, 0, 50) > at(&t, ECO_SUNNINESS, 0, -50) + 0.04f);
    eco_terrain_free(&t);
}

TEST(ridge_lee_sheltered_from_the_west_wind)
{
    eco_terrain t = build(ridge_ns, fixture_factor_params(40)); /* wind from the west (270) */
    CHECK_NEAR(at(&t, ECO_WINDINESS, -50, 0), 1.0, 0);   /* windward face */
    CHECK_NEAR(at(&t, ECO_WINDINESS, -150, 0), 1.0, 0);
    float lee = at(&t, ECO_WINDINESS, 20, 0);
    CHECK(lee < 0.85f);
    CHECK(at(&t, ECO_WINDINESS, 195, 0) > 0.95f); /* past N_w patches the crest no longer shelters */
    /* with the wind from the east the faces swap */
    eco_factor_params fp = fixture_factor_params(40);
    fp.wind_azimuth_deg = 90;
    eco_terrain e = build(ridge_ns, fp);
    CHECK_NEAR(at(&e, ECO_WINDINESS, 50, 0), 1.0, 0);
    CHECK(at(&e, ECO_WINDINESS, -20, 0) < 0.85f);
    eco_terrain_free(&t);
    eco_terrain_free(&e);
}

TEST(shelter_angle_by_hand)
{
    eco_terrain t = build(ridge_ns, fixture_factor_params(40));
    /* patch centred at x = 15 (i = 21); marching west the highest centre is the crest patch
     * x = 5 (z = 19), 10 m away, seen from z = 17: atan(2 / 10); farther ones are lower. */
    size_t p = 21 + 20 * (size_t)t.ni;
    CHECK_NEAR(t.cz[p], 17.0, 1e-5);
    CHECK_NEAR(eco_shelter_angle(&t, p, -1, 0, 10), atan(2.0 / 10.0), 1e-6);
    /* windiness 1 - φ/Θ0 with Θ0 = 45 degrees */
    CHECK_NEAR(t.factor[ECO_WINDINESS][p], 1.0 - atan(0.2) / (M_PI / 4), 1e-6);
    /* nothing upwind to the east of the east foot: exposed */
    CHECK_NEAR(eco_shelter_angle(&t, p, 1, 0, 10), 0.0, 0);
    eco_terrain_free(&t);
}

TEST(valley_collects_humidity)
{
    eco_terrain t = build(valley, fixture_factor_params(40));
    float bottom = at(&t, ECO_HUMIDITY, 5, 0), side = at(&t, ECO_HUMIDITY, 105, 0), top = at(&t, ECO_HUMIDITY, 195, 0);
    CHECK(bottom > side);
    CHECK(side > top);
    CHECK_NEAR(bottom, 1.0, 1e-6); /* the wettest land */
    CHECK_NEAR(top, 0.0, 0.05);
    eco_terrain_free(&t);
}

TEST(valley_water_patches_wettest)
{
    eco_factor_params fp = fixture_factor_params(40);
    fp.water_altitude = 0.05; /* the two bottom columns (x = -5 and 5, altitude 0.025) */
    eco_terrain t = build(valley, fp);
    int n_water = 0;
    float driest_water = 1, wettest_land = 0;
    for (size_t p = 0; p < (size_t)t.ni * t.nk; p++) {
        if (t.water[p]) n_water++, driest_water = fminf(driest_water, t.factor[ECO_HUMIDITY][p]);
        else wettest_land = fmaxf(wettest_land, t.factor[ECO_HUMIDITY][p]);
    }
    CHECK_INT(n_water, 2 * 40);
    CHECK_NEAR(driest_water, 1.0, 0);
    CHECK(wettest_land <= driest_water);
    CHECK(at(&t, ECO_HUMIDITY, 15, 0) > at(&t, ECO_HUMIDITY, 35, 0)); /* wetter beside the water */
    CHECK(eco_in_water(&t, 3, 10));
    CHECK(!eco_in_water(&t, 30, 10));
    eco_terrain_free(&t);
}

TEST(humidity_runoff_by_hand)
{
    /* Three patches in a row falling eastward, slope 0.5 each, no blur: Algorithm 3 moves
     * 1 * 0.5 from the first to the second, then 1.5 * 0.5 from the second to the third. */
    eco_terrain t = {.ni = 3, .nk = 1};
    double cz[3] = {2, 1, 0};
    float slope[3] = {0.5f, 0.5f, 0.5f}, hum[3];
    uint8_t water[3] = {0, 0, 0};
    t.cz = cz, t.water = water, t.factor[ECO_SLOPE] = slope, t.factor[ECO_HUMIDITY] = hum;
    eco_factor_params fp = fixture_factor_params(3);
    fp.humidity_blur = 0;
    CHECK_INT(eco_humidity(&t, &fp), 0);
    /* m = 0.5, 0.75, 1.75, normalised by min 0.5 and max 1.75 */
    CHECK_NEAR(hum[0], 0.0, 1e-7);
    CHECK_NEAR(hum[1], 0.2, 1e-7);
    CHECK_NEAR(hum[2], 1.0, 1e-7);
    /* one blur pass over the raw values 0.5, 0.75, 1.75: the border averages over what exists */
    fp.humidity_blur = 1;
    CHECK_INT(eco_humidity(&t, &fp), 0);
    double b0 = (0.5 + 0.75) / 2, b1 = (0.5 + 0.75 + 1.75) / 3, b2 = (0.75 + 1.75) / 2;
    CHECK_NEAR(hum[1], (b1 - b0) / (b2 - b0), 1e-6);
}

TEST(sun_path_for_a_latitude)
{
    double d[3], w;
    double alpha = (2.0 / M_PI) * asin(sin(23.5 * M_PI / 180) / cos(46 * M_PI / 180));
    eco_sun_sample(46, 9, 0, d, &w); /* sunrise: east, sin(α) north, on the horizon */
    CHECK_NEAR(d[1] / d[0], sin(alpha), 1e-12);
    CHECK_NEAR(sin(alpha), 0.3795, 5e-4);
    CHECK_NEAR(d[2], 0.0, 1e-12);
    CHECK_NEAR(w, 1.0, 1e-12);
    eco_sun_sample(46, 9, 4, d, &w); /* noon: south at 44 degrees, weight 2 */
    CHECK_NEAR(d[0], 0.0, 1e-12);
    CHECK_NEAR(d[1], -cos(44 * M_PI / 180), 1e-12);
    CHECK_NEAR(d[2], sin(44 * M_PI / 180), 1e-12);
    CHECK_NEAR(w, 2.0, 1e-12);
    eco_sun_sample(46, 9, 8, d, &w); /* sunset: west */
    CHECK(d[0] < -0.9);
    CHECK_NEAR(w, 1.0, 1e-12);
    eco_sun_sample(46, 9, 6, d, &w);
    CHECK_NEAR(w, 1.5, 1e-12);
    CHECK(d[0] < 0 && d[2] > 0);
    eco_sun_sample(-30, 9, 4, d, &w); /* south of the equator noon is in the north */
    CHECK_NEAR(d[1], cos(60 * M_PI / 180), 1e-12);
}

TEST(shadow_behind_a_wall)
{
    /* a 60 m wall along x = 0 shadows the patch just west of it at sunset only */
    eco_terrain t = build(ridge_ns, fixture_factor_params(40));
    size_t p = 10 + 20 * (size_t)t.ni; /* x = -95, at the west foot */
    double z_max = 0;
    for (size_t q = 0; q < (size_t)t.ni * t.nk; q++) z_max = fmax(z_max, t.cz[q]);
    double d[3], w;
    eco_sun_sample(46, 9, 0, d, &w); /* sunrise, behind the ridge, on the horizon */
    CHECK(eco_in_shadow(&t, z_max, p, d));
    eco_sun_sample(46, 9, 4, d, &w); /* noon, high in the south */
    CHECK(!eco_in_shadow(&t, z_max, p, d));
    eco_sun_sample(46, 9, 8, d, &w); /* sunset, in the open west */
    CHECK(!eco_in_shadow(&t, z_max, p, d));
    eco_terrain_free(&t);
}

TEST(patch_grid_follows_the_longer_side)
{
    sylva_heightfield hf = fixture_heightfield(21, 11, 0, 0, 10, flat); /* 200 x 100 m */
    eco_factor_params fp = fixture_factor_params(50);
    eco_terrain t;
    char msg[256];
    CHECK_INT(eco_terrain_build(&t, &hf, &fp, msg, sizeof msg), 0);
    CHECK_INT(t.ni, 50);
    CHECK_INT(t.nk, 25);
    CHECK_NEAR(t.kx, 4.0, 1e-12);
    CHECK_NEAR(t.ky, 4.0, 1e-12);
    CHECK_INT(eco_patch_of(&t, 199.9, 99.9), 49 + 24 * 50);
    CHECK_INT(eco_patch_of(&t, -0.1, 5), -1);
    eco_terrain_free(&t);
    free(hf.z);
}

TEST(threads_give_the_same_factors)
{
    eco_factor_params fp = fixture_factor_params(40);
    eco_terrain a = build(ridge_ew, fp);
    fp.threads = 3;
    eco_terrain b = build(ridge_ew, fp);
    size_t n = (size_t)a.ni * a.nk;
    for (int f = 0; f < ECO_N_FACTORS; f++) CHECK(!memcmp(a.factor[f], b.factor[f], n * sizeof(float)));
    eco_terrain_free(&a);
    eco_terrain_free(&b);
}

TEST_LIST(TEST_CASE(flat_plane), TEST_CASE(ridge_south_face_sunnier_and_slopes),
          TEST_CASE(ridge_sun_mirrors_south_of_the_equator), TEST_CASE(ridge_lee_sheltered_from_the_west_wind),
          TEST_CASE(shelter_angle_by_hand), TEST_CASE(valley_collects_humidity),
          TEST_CASE(valley_water_patches_wettest), TEST_CASE(humidity_runoff_by_hand),
          TEST_CASE(sun_path_for_a_latitude), TEST_CASE(shadow_behind_a_wall),
          TEST_CASE(patch_grid_follows_the_longer_side), TEST_CASE(threads_give_the_same_factors))
