/* test_leaf_affine.c — leaves by affine maps (003 §2): the rendered attractor is a fixed point
 * of its maps' Hutchinson operator within one texel, known map sets give their known shapes
 * (square, triangle) with the right area and outline, the presets give leaves with a midrib,
 * user maps are parsed or refused with a sentence, and the bytes repeat for a seed. */
#include "harness.h"
#include "leaf_affine.h"

#include <stdint.h>

/* Four half-size copies of the square [0.1, 0.9]^2: its attractor is that square. */
static leaf_affine_maps square_maps(void)
{
    leaf_affine_maps m = {0};
    leaf_affine_parse("0.5 0 0 0.5 0.05 0.05; 0.5 0 0 0.5 0.45 0.05;"
                      "0.5 0 0 0.5 0.05 0.45; 0.5 0 0 0.5 0.45 0.45", &m, NULL, 0);
    return m;
}

/* The triangle (0.1, 0.1), (0.9, 0.1), (0.5, 0.9) as its three corner halves and the middle
 * half turned through 180 degrees about the centroid: its attractor is the filled triangle. */
static leaf_affine_maps triangle_maps(void)
{
    leaf_affine_maps m = {0};
    leaf_affine_parse("0.5 0 0 0.5 0.05 0.05\n0.5 0 0 0.5 0.45 0.05\n0.5 0 0 0.5 0.25 0.45\n"
                      "-0.5 0 0 -0.5 0.75 0.55", &m, NULL, 0);
    return m;
}

static int near_hit(const leaf_affine_raster *r, int32_t col, int32_t row)
{
    int32_t n = (int32_t)r->size;
    for (int32_t j = row - 1; j <= row + 1; j++)
        for (int32_t i = col - 1; i <= col + 1; i++)
            if (i >= 0 && j >= 0 && i < n && j < n && r->hit[(size_t)j * n + i]) return 1;
    return 0;
}

/* Texels of the Hutchinson image of r under maps that are not within one texel of r, plus
 * texels of r not within one texel of the image. */
static size_t hutchinson_misses(const leaf_affine_raster *r, const leaf_affine_maps *maps)
{
    uint32_t n = r->size;
    uint8_t *image = calloc((size_t)n * n, 1); /* owned here */
    size_t misses = 0;
    for (uint32_t row = 0; row < n; row++)
        for (uint32_t col = 0; col < n; col++) {
            if (!r->hit[(size_t)row * n + col]) continue;
            double u = (col + 0.5) / n, v = 1 - (row + 0.5) / n;
            for (uint32_t k = 0; k < maps->n; k++) {
                double x, y;
                leaf_affine_apply(&maps->map[k], u, v, &x, &y);
                int32_t c = (int32_t)floor(x * n), w = (int32_t)floor((1 - y) * n);
                if (c >= 0 && w >= 0 && c < (int32_t)n && w < (int32_t)n) image[(size_t)w * n + c] = 1;
                if (!near_hit(r, c, w)) misses++;
            }
        }
    leaf_affine_raster back = {n, image, NULL};
    for (uint32_t row = 0; row < n; row++)
        for (uint32_t col = 0; col < n; col++)
            if (r->hit[(size_t)row * n + col] && !near_hit(&back, (int32_t)col, (int32_t)row)) misses++;
    free(image);
    return misses;
}

static size_t count(const uint8_t *mask, size_t texels)
{
    size_t c = 0;
    for (size_t i = 0; i < texels; i++) c += mask[i] != 0;
    return c;
}

TEST(hutchinson_fixed_point)
{
    leaf_affine_maps sets[LEAF_AFFINE_PRESET_COUNT + 2];
    for (uint32_t p = 0; p < LEAF_AFFINE_PRESET_COUNT; p++) leaf_affine_preset_maps(p, &sets[p]);
    sets[LEAF_AFFINE_PRESET_COUNT] = square_maps();
    sets[LEAF_AFFINE_PRESET_COUNT + 1] = triangle_maps();
    for (uint32_t s = 0; s < LEAF_AFFINE_PRESET_COUNT + 2; s++) {
        leaf_affine_raster r;
        char err[256];
        CHECK_INT(leaf_affine_attractor(&sets[s], 128, 7, &r, err, sizeof err), 0);
        CHECK_INT(hutchinson_misses(&r, &sets[s]), 0);
        leaf_affine_raster_free(&r);
    }
    /* The check can fail: the square's raster is no fixed point of the triangle's maps. */
    leaf_affine_raster r;
    leaf_affine_maps square = square_maps(), triangle = triangle_maps();
    CHECK_INT(leaf_affine_attractor(&square, 128, 7, &r, NULL, 0), 0);
    CHECK(hutchinson_misses(&r, &triangle) > 100);
    leaf_affine_raster_free(&r);
}

TEST(square_area)
{
    const uint32_t n = 256;
    leaf_affine_maps m = square_maps();
    leaf_affine_raster r;
    CHECK_INT(leaf_affine_attractor(&m, n, 1, &r, NULL, 0), 0);
    uint8_t *inside = malloc((size_t)n * n);
    CHECK_INT(leaf_affine_outline(&r, inside), 0);
    double area = (double)count(r.hit, (size_t)n * n) / ((double)n * n);
    CHECK_NEAR(area, 0.64, 0.64 * 0.02);
    CHECK_NEAR((double)count(inside, (size_t)n * n) / ((double)n * n), 0.64, 0.64 * 0.02);
    free(inside);
    leaf_affine_raster_free(&r);
}

/* Signed distance (in texels, positive inside) of (u, v) from the triangle's nearest edge. */
static double triangle_depth(double u, double v, uint32_t n)
{
    const double px[3] = {0.1, 0.9, 0.5}, py[3] = {0.1, 0.1, 0.9};
    double depth = 1e9;
    for (int k = 0; k < 3; k++) {
        double ax = px[k], ay = py[k], bx = px[(k + 1) % 3], by = py[(k + 1) % 3];
        double ex = bx - ax, ey = by - ay, len = hypot(ex, ey);
        double d = (ex * (v - ay) - ey * (u - ax)) / len; /* anticlockwise: inside is left */
        if (d < depth) depth = d;
    }
    return depth * n;
}

TEST(triangle_area_and_outline)
{
    const uint32_t n = 256;
    leaf_affine_maps m = triangle_maps();
    uint8_t *rgba = malloc((size_t)n * n * 4);
    char err[256] = "";
    CHECK_INT(leaf_affine_render(&m, n, 3, rgba, err, sizeof err), 0);
    size_t inside = 0, wrong = 0;
    for (uint32_t row = 0; row < n; row++)
        for (uint32_t col = 0; col < n; col++) {
            int alpha = rgba[((size_t)row * n + col) * 4 + 3];
            CHECK(alpha == 0 || alpha == 255);
            inside += alpha == 255;
            double depth = triangle_depth((col + 0.5) / n, 1 - (row + 0.5) / n, n);
            if ((depth > 1 && alpha != 255) || (depth < -1 && alpha != 0)) wrong++;
        }
    CHECK_INT(wrong, 0);
    CHECK_NEAR((double)inside / ((double)n * n), 0.32, 0.32 * 0.03);
    free(rgba);
}

TEST(presets_are_leaves_with_a_midrib)
{
    const uint32_t n = 128;
    for (uint32_t p = 0; p < LEAF_AFFINE_PRESET_COUNT; p++) {
        leaf_affine_maps m;
        leaf_affine_preset_maps(p, &m);
        CHECK(leaf_affine_preset_name(p) != NULL);
        CHECK_INT(leaf_affine_check(&m, NULL, 0), 0);
        leaf_affine_raster r;
        CHECK_INT(leaf_affine_attractor(&m, n, 5, &r, NULL, 0), 0);
        uint8_t *inside = malloc((size_t)n * n);
        CHECK_INT(leaf_affine_outline(&r, inside), 0);
        double cover = (double)count(inside, (size_t)n * n) / ((double)n * n);
        /* broad blades cover a good part of the square, the needle twig and willow much less */
        if (p == LEAF_AFFINE_SPRUCE || p == LEAF_AFFINE_WILLOW) CHECK(cover > 0.05 && cover < 0.3);
        else CHECK(cover > 0.2 && cover < 0.8);
        /* the midrib runs up the middle column from the stalk to past 3/4 of the length */
        size_t rib = 0, veins = 0;
        for (uint32_t row = n / 4; row < n; row++) rib += r.order[(size_t)row * n + n / 2] == 0;
        for (size_t t = 0; t < (size_t)n * n; t++) veins += r.order[t] == 1;
        CHECK(rib >= (size_t)(0.7 * n));
        CHECK(veins > n / 2);
        CHECK(inside[(size_t)(n - 1) * n + n / 2]); /* the stalk reaches v = 0 */
        free(inside);
        leaf_affine_raster_free(&r);
    }
    CHECK(leaf_affine_preset_name(LEAF_AFFINE_PRESET_COUNT) == NULL);
}

TEST(veins_are_lighter_than_the_blade)
{
    const uint32_t n = 128;
    leaf_affine_maps m;
    leaf_affine_preset_maps(LEAF_AFFINE_BEECH, &m);
    uint8_t *rgba = malloc((size_t)n * n * 4);
    leaf_affine_raster r;
    CHECK_INT(leaf_affine_render(&m, n, 9, rgba, NULL, 0), 0);
    CHECK_INT(leaf_affine_attractor(&m, n, 9, &r, NULL, 0), 0);
    double sum[3] = {0}, num[3] = {0};
    for (size_t t = 0; t < (size_t)n * n; t++) {
        if (rgba[t * 4 + 3] != 255) continue;
        int k = r.order[t] == 0 ? 0 : r.order[t] == 1 ? 1 : 2;
        sum[k] += rgba[t * 4], num[k]++;
        CHECK(rgba[t * 4] == rgba[t * 4 + 1] && rgba[t * 4] == rgba[t * 4 + 2]);
    }
    CHECK(num[0] > 0 && num[1] > 0 && num[2] > 0);
    CHECK(sum[0] / num[0] > sum[1] / num[1]);
    CHECK(sum[1] / num[1] > sum[2] / num[2] + 5);
    free(rgba);
    leaf_affine_raster_free(&r);
}

TEST(deterministic_bytes)
{
    const uint32_t n = 64;
    size_t bytes = (size_t)n * n * 4;
    uint8_t *a = malloc(bytes), *b = malloc(bytes), *c = malloc(bytes);
    leaf_affine_maps m;
    leaf_affine_preset_maps(LEAF_AFFINE_MAPLE, &m);
    CHECK_INT(leaf_affine_render(&m, n, 42, a, NULL, 0), 0);
    CHECK_INT(leaf_affine_render(&m, n, 43, c, NULL, 0), 0);
    CHECK_INT(leaf_affine_render(&m, n, 42, b, NULL, 0), 0);
    CHECK(memcmp(a, b, bytes) == 0);
    CHECK(memcmp(a, c, bytes) != 0);
    free(a), free(b), free(c);
}

TEST(parse_user_maps)
{
    leaf_affine_maps m;
    char err[256] = "";
    CHECK_INT(leaf_affine_parse(" 0.5,0,0,0.5,0,0, 1 ;0.5 0 0 0.5 0.5 0.5 3\n", &m, err, sizeof err), 0);
    CHECK_INT(m.n, 2);
    CHECK_NEAR(m.map[1].e, 0.5, 0);
    CHECK_NEAR(m.map[1].p, 3, 0);
    CHECK_INT(leaf_affine_parse("0 0 0 0.16 0 0; 0.5 0 0 0.5 0 0", &m, err, sizeof err), 0);
    CHECK_NEAR(m.map[0].p, 0.01, 1e-12); /* a singular map keeps a small weight */
    CHECK_NEAR(m.map[1].p, 0.25, 1e-12); /* |det| */

    static const char *const bad[][2] = {
        {"0.5 0 0 0.5 0 0; 0.5 0 0 0.5 0", "column 18: map 2 has 5 numbers; give 6"},
        {"0.5 0 0 0.5 0 x", "column 15: 'x' is not a number"},
        {"0.5 0 0 0.5 0 0 1; 0.5 0 0 0.5 0 0", "every map or for none"},
        {"1.2 0 0 0.5 0 0", "map 1 stretches by 1.2"},
        {"0.5 0 0 0.5 0 0 -1", "weight -1 must be greater than 0"},
        {" ; \n", "no maps given"},
        {"0.5 0 0 0.5 0 0 1 2", "column 19: map 1 has more than 7 numbers"},
        {"1e999 0 0 0.5 0 0", "not a finite number"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        err[0] = 0;
        CHECK_INT(leaf_affine_parse(bad[i][0], &m, err, sizeof err), -1);
        CHECK_STR_CONTAINS(err, bad[i][1]);
    }
}

TEST(attractor_outside_the_square_is_refused)
{
    leaf_affine_maps m;
    CHECK_INT(leaf_affine_parse("0.5 0 0 0.5 0.8 0", &m, NULL, 0), 0); /* fixed point (1.6, 0) */
    leaf_affine_raster r;
    char err[256] = "";
    CHECK_INT(leaf_affine_attractor(&m, 64, 1, &r, err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, "outside the unit square");
    CHECK(r.hit == NULL && r.order == NULL);
    leaf_affine_maps square = square_maps();
    CHECK_INT(leaf_affine_attractor(&square, 8, 1, &r, err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, "texture size 8 is outside 16..2048");
    leaf_affine_raster_free(NULL);
}

TEST_LIST(TEST_CASE(hutchinson_fixed_point), TEST_CASE(square_area),
          TEST_CASE(triangle_area_and_outline), TEST_CASE(presets_are_leaves_with_a_midrib),
          TEST_CASE(veins_are_lighter_than_the_blade), TEST_CASE(deterministic_bytes),
          TEST_CASE(parse_user_maps), TEST_CASE(attractor_outside_the_square_is_refused))
