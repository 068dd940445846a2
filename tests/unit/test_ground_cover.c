/* Ground-cover weights (geometry/ground_cover.h): each rule picks its kind, the weights sum to
 * one and are continuous everywhere (no jump at a cell's edge, as per-node classes had), the
 * canopy comes from the plants' crowns, a terrain without ground rules keeps its materials, and
 * the scene's lying snow (snow:) covers its share of the open ground above its height; the meadow
 * rests out of its growing season (dull in winter, lush in summer, greening up in spring). */
#include "geometry/ground_cover.h"
#include "ground_fixture.h"
#include "season/phenology.h"
#include "harness.h"

static double flat10(double x, double y) { (void)x, (void)y; return 10; }
static double flat90(double x, double y) { (void)x, (void)y; return 90; }
static double flat150(double x, double y) { (void)x, (void)y; return 150; }
static double steep(double x, double y) { (void)y; return 10 + tan(60 * M_PI / 180) * x; }
/* Hills from about 15 to 125 m with slopes from flat to over 50 degrees: every rule in play. */
static double hills(double x, double y)
{
    return 55 + 35 * sin(x / 40.0) * cos(y / 50.0) + 6 * sin((x + 2 * y) / 15.0) + 0.15 * x;
}

/* The mean weight of kind k over a 200 m square of n x n points. */
static double mean_weight(const ground_cover_map *m, ground_kind k)
{
    double sum = 0;
    int n = 40;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            float w[GROUND_KINDS];
            ground_cover_weights(m, 5 + i * 190.0 / n, 5 + j * 190.0 / n, w);
            sum += w[k];
        }
    return sum / (n * n);
}

static ground_cover_map *map_of(scene *s)
{
    err_buf err = {{0}};
    ground_cover_map *m = ground_cover_map_new(s, &err);
    CHECK(m != NULL);
    CHECK_INT(err.msg[0], 0);
    return m;
}

TEST(each_rule_picks_its_kind)
{
    static const struct {
        double (*height)(double, double);
        ground_kind kind;
        double at_least;
    } cases[] = {{flat10, GROUND_MEADOW, 0.85}, {steep, GROUND_ROCK, 0.95}, {flat150, GROUND_SNOW, 0.95},
                 {flat90, GROUND_SCREE, 0.95}};
    for (size_t c = 0; c < sizeof cases / sizeof *cases; c++) {
        scene *s = fixture_scene(51, 51, 0, 0, 4, cases[c].height, 1);
        ground_cover_map *m = map_of(s);
        double got = m ? mean_weight(m, cases[c].kind) : 0;
        if (!(got >= cases[c].at_least))
            fprintf(stderr, "case %zu: mean %s weight %.3f, expected at least %.2f\n", c,
                    ground_kind_name(cases[c].kind), got, cases[c].at_least);
        CHECK(got >= cases[c].at_least);
        ground_cover_map_free(m);
        scene_free(s);
    }
    /* under water: the water's edge; above it by metres: none */
    scene *s = fixture_scene(51, 51, 0, 0, 4, flat10, 1);
    s->terrain->has_water = 1, s->terrain->water_level = 12;
    ground_cover_map *m = map_of(s);
    CHECK(m && mean_weight(m, GROUND_WATER) > 0.99);
    ground_cover_map_free(m);
    s->terrain->water_level = 5;
    m = map_of(s);
    CHECK(m && mean_weight(m, GROUND_WATER) == 0);
    ground_cover_map_free(m);
    scene_free(s);
}

TEST(canopy_from_the_crowns)
{
    scene *s = fixture_scene(51, 51, -100, -100, 4, flat10, 1);
    CHECK_INT(fixture_plant(s, 0, 0, 6, 20), 0);   /* a tree with a 12 m crown */
    CHECK_INT(fixture_plant(s, 50, 50, 1, 0.5), 0); /* a seedling: no litter */
    ground_cover_map *m = map_of(s);
    if (!m) return;
    CHECK(ground_cover_canopy(m, 0, 0) > 0.85);
    CHECK(ground_cover_canopy(m, 3, 0) > 0.85);
    CHECK_NEAR(ground_cover_canopy(m, 12, 0), 0, 1e-6); /* beyond 1.3 crown radii */
    CHECK_NEAR(ground_cover_canopy(m, 50, 50), 0, 1e-6);
    float w[GROUND_KINDS];
    ground_cover_weights(m, 0, 0, w);
    CHECK(w[GROUND_FOREST_FLOOR] > 0.8);
    ground_cover_weights(m, 30, 0, w);
    CHECK_NEAR(w[GROUND_FOREST_FLOOR], 0, 1e-6);
    ground_cover_map_free(m);
    scene_free(s);
}

TEST(dry_grass_from_the_humidity)
{
    scene *s = fixture_scene(11, 11, 0, 0, 20, flat10, 1);
    ground_cover_map *m = map_of(s);
    CHECK_NEAR(m ? ground_cover_dryness(m, 100, 100) : -1, 0, 0); /* no humidity map: lush */
    ground_cover_map_free(m);
    s->terrain->humidity = malloc(121 * sizeof(float));
    for (int k = 0; k < 121; k++) s->terrain->humidity[k] = (k % 11) < 5 ? 0.05f : 0.9f; /* dry west */
    m = map_of(s);
    if (m) {
        CHECK_NEAR(ground_cover_dryness(m, 20, 100), 1, 1e-6);
        CHECK_NEAR(ground_cover_dryness(m, 180, 100), 0, 1e-6);
    }
    ground_cover_map_free(m);
    scene_free(s);
}

TEST(weights_sum_to_one_and_are_continuous)
{
    scene *s = fixture_scene(51, 51, 0, 0, 4, hills, 1);
    s->terrain->has_water = 1, s->terrain->water_level = 30;
    for (int k = 0; k < 12; k++) CHECK_INT(fixture_plant(s, 20 + 13 * k, 40 + 9 * (k % 5), 3 + k % 4, 8 + k), 0);
    ground_cover_map *m = map_of(s);
    if (!m) return;
    /* every kind appears somewhere on these hills */
    for (int k = 0; k < GROUND_KINDS; k++) {
        double got = mean_weight(m, (ground_kind)k);
        fprintf(stderr, "%s: mean %.4f\n", ground_kind_name((ground_kind)k), got);
        if (!(got > 0.001)) fprintf(stderr, "%s never appears (mean %.4f)\n", ground_kind_name((ground_kind)k), got);
        CHECK(got > 0.001);
    }
    /* along lines across the cells 1 cm apart: the sum is one, each weight in [0, 1], and no
     * weight moves by more than 0.2 in a centimetre (the steepest edge here, the water's on a bank
     * of 80 degrees, moves it by about 0.06; a jump at a cell edge or a class boundary, as
     * per-node classes made, moves it by up to 1) */
    double worst_sum = 0, worst_step = 0;
    for (int line = 0; line < 4; line++) {
        float prev[GROUND_KINDS];
        for (int q = 0; q <= 19000; q++) {
            double t = 0.01 * q, x = 5 + t, y = 7 + 47.3 * line + 0.37 * t;
            float w[GROUND_KINDS];
            ground_cover_weights(m, x, y, w);
            double sum = 0;
            for (int k = 0; k < GROUND_KINDS; k++) {
                sum += w[k];
                CHECK(w[k] >= 0 && w[k] <= 1);
                if (q) worst_step = fmax(worst_step, fabs(w[k] - prev[k]));
                prev[k] = w[k];
            }
            worst_sum = fmax(worst_sum, fabs(sum - 1));
        }
    }
    CHECK_NEAR(worst_sum, 0, 1e-5);
    CHECK(worst_step < 0.2);
    if (!(worst_step < 0.2)) fprintf(stderr, "largest change over 1 cm: %.4f\n", worst_step);
    /* exactly at cell edges: the two sides agree */
    for (int i = 1; i < 50; i++) {
        float a[GROUND_KINDS], b[GROUND_KINDS];
        ground_cover_weights(m, 4.0 * i - 1e-6, 61.3, a);
        ground_cover_weights(m, 4.0 * i + 1e-6, 61.3, b);
        for (int k = 0; k < GROUND_KINDS; k++) CHECK_NEAR(a[k], b[k], 1e-4);
    }
    ground_cover_map_free(m);
    scene_free(s);
}

TEST(terrain_without_rules_keeps_its_materials)
{
    scene *s = fixture_scene(11, 11, 0, 0, 10, flat10, 0);
    err_buf err = {{0}};
    CHECK(ground_cover_map_new(s, &err) == NULL);
    CHECK_INT(err.msg[0], 0);
    scene_free(s);
    s = scene_new(); /* no terrain at all */
    CHECK(ground_cover_map_new(s, &err) == NULL);
    CHECK_INT(err.msg[0], 0);
    scene_free(s);
    ground_cover_map_free(NULL);
    CHECK_STR_CONTAINS(ground_kind_name(GROUND_FOREST_FLOOR), "forest floor");
}

/* The mean weight of kind k on map m of scene s with snow settings w. */
static double mean_with_snow(scene *s, snow_settings w, ground_kind k)
{
    s->snow = w;
    ground_cover_map *m = map_of(s);
    double got = m ? mean_weight(m, k) : -1;
    ground_cover_map_free(m);
    return got;
}

TEST(lying_snow_covers_its_share_above_its_height)
{
    scene *s = fixture_scene(51, 51, 0, 0, 4, flat10, 1);
    CHECK(s != NULL);
    if (!s) return;
    const double everywhere = -HUGE_VAL;
    CHECK_NEAR(mean_with_snow(s, (snow_settings){0, 1, everywhere}, GROUND_SNOW), 0, 0); /* off: meadow */
    CHECK(mean_with_snow(s, (snow_settings){1, 1, everywhere}, GROUND_SNOW) > 0.99);
    CHECK_NEAR(mean_with_snow(s, (snow_settings){1, 0, everywhere}, GROUND_SNOW), 0, 0);
    /* a partial cover: its share of the ground, in patches */
    static const double covers[] = {0.25, 0.6, 0.9};
    for (size_t i = 0; i < sizeof covers / sizeof *covers; i++) {
        double got = mean_with_snow(s, (snow_settings){1, covers[i], everywhere}, GROUND_SNOW);
        fprintf(stderr, "cover %.2f: mean snow weight %.3f\n", covers[i], got);
        CHECK_NEAR(got, covers[i], 0.08);
    }
    /* above its height only: 10 m ground under snow from 5 m, not under snow from 20 m */
    CHECK(mean_with_snow(s, (snow_settings){1, 1, 5}, GROUND_SNOW) > 0.99);
    CHECK_NEAR(mean_with_snow(s, (snow_settings){1, 1, 20}, GROUND_SNOW), 0, 0);
    scene_free(s);
    /* it slides off 60-degree ground, as the snow line's does */
    s = fixture_scene(51, 51, 0, 0, 4, steep, 1);
    CHECK(s && mean_with_snow(s, (snow_settings){1, 1, everywhere}, GROUND_SNOW) < 0.01);
    scene_free(s);
}

TEST(meadow_rests_out_of_its_growing_season)
{
    CHECK_NEAR(meadow_dormancy(0), 0, 0);   /* no season given: summer */
    CHECK_NEAR(meadow_dormancy(SEASON_SUMMER_DAY), 0, 0);
    CHECK_NEAR(meadow_dormancy(SEASON_WINTER_DAY), 1, 0);
    CHECK_NEAR(meadow_dormancy(350), 1, 0);
    CHECK_NEAR(meadow_dormancy(280), 0.5, 1e-12);  /* half cured between days 230 and 330 */
    CHECK_NEAR(meadow_dormancy(95), 0.5, 1e-12);   /* half green between days 60 and 130 */
    scene *s = fixture_scene(11, 11, 0, 0, 20, flat10, 1);
    s->terrain->humidity = malloc(121 * sizeof(float));
    for (int k = 0; k < 121; k++) s->terrain->humidity[k] = (k % 11) < 5 ? 0.05f : 0.9f; /* dry west */
    const uint32_t days[] = {SEASON_SUMMER_DAY, SEASON_AUTUMN_DAY, SEASON_WINTER_DAY};
    const double lush[] = {0, GROUND_MEADOW_REST_SHARE * (SEASON_AUTUMN_DAY - 230) / 100.0, GROUND_MEADOW_REST_SHARE};
    for (int d = 0; d < 3; d++) {
        s->season_day = days[d];
        ground_cover_map *m = map_of(s);
        if (!m) break;
        CHECK_NEAR(ground_cover_dryness(m, 180, 100), lush[d], 1e-6); /* the lush meadow rests */
        CHECK_NEAR(ground_cover_dryness(m, 20, 100), 1, 1e-6);        /* the dry one stays dry */
        ground_cover_map_free(m);
    }
    scene_free(s);
}

TEST_LIST(TEST_CASE(meadow_rests_out_of_its_growing_season), TEST_CASE(lying_snow_covers_its_share_above_its_height), TEST_CASE(each_rule_picks_its_kind), TEST_CASE(canopy_from_the_crowns), TEST_CASE(dry_grass_from_the_humidity),
          TEST_CASE(weights_sum_to_one_and_are_continuous), TEST_CASE(terrain_without_rules_keeps_its_materials))
