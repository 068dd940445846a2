/* test_bark_fractal.c — the fractal bark (src/plugins/common/bark_fractal.h): escape times of
 * z' = lambda z (1 - z) against hand-worked orbits and an independent complex-arithmetic
 * reference, the texture's determinism, its seam round the branch, its luminance rising with
 * height (what the renderer's bark bump reads), the normal map, and parameter checks. */
#include <complex.h>
#include <stdint.h>

#include "bark_fractal.h"
#include "harness.h"

#define GOLDEN_THETA 2.3999632297286531 /* 2 pi (1 - 1/phi): a Siegel disc at 0 */

/* The escape time written with C99 complex arithmetic, separately from the library's. */
static uint32_t reference_count(double theta, double complex z, uint32_t limit)
{
    double complex lambda = cexp(I * theta);
    for (uint32_t n = 0; n < limit; n++) {
        if (cabs(z) > 2.0) return n;
        z = lambda * z * (1.0 - z);
    }
    return limit;
}

TEST(spot_values_follow_hand_worked_orbits)
{
    /* |3| > 2 at once */
    CHECK_INT(bark_fractal_escape_count(GOLDEN_THETA, 3.0, 0.0, 100), 0);
    /* z0 = -1.5: z1 = lambda (-1.5)(2.5), |z1| = 3.75 whatever lambda */
    CHECK_INT(bark_fractal_escape_count(GOLDEN_THETA, -1.5, 0.0, 100), 1);
    /* z0 = -1: |z1| = |-2 lambda| = 2 stays; z2 = -2 lambda^2 (1 + 2 lambda), |z2| =
     * 2 sqrt(5 + 4 cos theta) = 2.864 for the golden angle: escapes at n = 2 ... */
    CHECK_INT(bark_fractal_escape_count(GOLDEN_THETA, -1.0, 0.0, 100), 2);
    /* theta = 0 (lambda = 1 exactly): from 1/2 the real orbit z (1 - z) falls toward 0 */
    CHECK_INT(bark_fractal_escape_count(0.0, 0.5, 0.0, 100), 100);
    /* and from 2: z1 = 2 (1 - 2) = -2 stays, z2 = -2 (1 + 2) = -6 escapes */
    CHECK_INT(bark_fractal_escape_count(0.0, 2.0, 0.0, 100), 2);
    /* 0 is the fixed point with multiplier lambda, 1 lands on it */
    CHECK_INT(bark_fractal_escape_count(GOLDEN_THETA, 0.0, 0.0, 100), 100);
    CHECK_INT(bark_fractal_escape_count(GOLDEN_THETA, 1.0, 0.0, 100), 100);
    /* the limit caps the count */
    CHECK_INT(bark_fractal_escape_count(GOLDEN_THETA, 0.0, 0.0, 7), 7);
}

TEST(counts_match_an_independent_reference_over_the_plane)
{
    const double thetas[3] = {GOLDEN_THETA, 1.8, 0.9};
    uint32_t differ_by_theta = 0, escaped = 0, inside = 0;
    for (int t = 0; t < 3; t++)
        for (int j = 0; j < 61; j++)
            for (int i = 0; i < 81; i++) {
                double re = -1.0 + 3.0 * i / 80.0, im = -1.2 + 2.4 * j / 60.0;
                uint32_t got = bark_fractal_escape_count(thetas[t], re, im, 60);
                uint32_t want = reference_count(thetas[t], re + I * im, 60);
                if (got != want) {
                    fprintf(stderr, "theta %g at %g%+gi: %u steps, reference %u\n", thetas[t], re, im, got, want);
                    CHECK_INT(got, want);
                }
                escaped += got > 0 && got < 60, inside += got == 60;
                if (t > 0) differ_by_theta += got != bark_fractal_escape_count(thetas[0], re, im, 60);
            }
    CHECK(escaped > 1000 && inside > 1000); /* the grid holds both sides of the set */
    CHECK(differ_by_theta > 500);            /* lambda changes the pattern */
}

TEST(smooth_count_and_distance_agree_with_the_count)
{
    for (int i = 0; i < 200; i++) {
        double re = -1.0 + 3.0 * i / 199.0, im = 0.37;
        uint32_t n = bark_fractal_escape_count(GOLDEN_THETA, re, im, 80);
        double nu = bark_fractal_escape_smooth(GOLDEN_THETA, re, im, 80);
        double d = bark_fractal_distance(GOLDEN_THETA, re, im, 80);
        if (n == 80) {
            CHECK_NEAR(nu, 80, 0);
            CHECK_NEAR(d, 0, 0);
        } else {
            /* the smooth count is the step |z| passes 256, some steps after it passes 2 */
            CHECK(nu >= n && nu <= n + 10.0);
            CHECK(d > 0);
        }
    }
    /* far out, z0 = 100 lies about 99 from the set; the estimate is within a small factor */
    double d = bark_fractal_distance(GOLDEN_THETA, 100.0, 0.0, 80);
    CHECK(d > 99.0 / 4 && d < 99.0 * 4);
}

static float *heights_of(const bark_fractal_params *p, uint32_t w, uint32_t h)
{
    float *out = malloc((size_t)w * h * sizeof *out); /* owned by the caller */
    bark_fractal_heights(p, w, h, out);
    return out;
}

TEST(textures_are_deterministic)
{
    const uint32_t n = 96;
    for (int k = 0; k < BARK_FRACTAL_PRESETS; k++) {
        bark_fractal_params p = bark_fractal_preset_params((bark_fractal_preset)k);
        float *a = heights_of(&p, n, n), *b = heights_of(&p, n, n);
        uint8_t *ca = malloc((size_t)n * n * 4), *cb = malloc((size_t)n * n * 4);
        bark_fractal_albedo(&p, n, n, a, ca);
        bark_fractal_albedo(&p, n, n, b, cb);
        CHECK(memcmp(a, b, (size_t)n * n * sizeof *a) == 0);
        CHECK(memcmp(ca, cb, (size_t)n * n * 4) == 0);
        free(a), free(b), free(ca), free(cb);
    }
}

/* Mean |h(x) - h(x+1)| over the texture's interior columns and over its seam (last column to
 * the first): a pattern that closes round the branch has no larger step at the seam. */
static void seam_and_interior_steps(const float *h, uint32_t w, uint32_t rows, double *seam, double *inner)
{
    double s = 0, in = 0;
    for (uint32_t r = 0; r < rows; r++) {
        for (uint32_t x = 0; x + 1 < w; x++) in += fabs(h[r * w + x + 1] - h[r * w + x]);
        s += fabs(h[r * w] - h[r * w + w - 1]);
    }
    *seam = s / rows, *inner = in / ((double)rows * (w - 1));
}

TEST(pattern_closes_round_the_branch)
{
    const uint32_t w = 128, rows = 128;
    for (int k = 0; k < BARK_FRACTAL_PRESETS; k++) {
        bark_fractal_params p = bark_fractal_preset_params((bark_fractal_preset)k);
        /* the plane point itself is periodic in u and in v */
        for (int i = 0; i < 16; i++) {
            double v = i / 16.0 + 0.01, a_re, a_im, b_re, b_im;
            bark_fractal_point(&p, 0.0, v, &a_re, &a_im);
            bark_fractal_point(&p, 1.0, v, &b_re, &b_im);
            CHECK_NEAR(a_re, b_re, 1e-12);
            CHECK_NEAR(a_im, b_im, 1e-12);
            bark_fractal_point(&p, v, 1.0 + 0.25, &b_re, &b_im);
            bark_fractal_point(&p, v, 0.25, &a_re, &a_im);
            CHECK_NEAR(a_re, b_re, 1e-12);
            CHECK_NEAR(a_im, b_im, 1e-12);
        }
        float *h = heights_of(&p, w, rows);
        double seam, inner;
        seam_and_interior_steps(h, w, rows, &seam, &inner);
        CHECK(seam <= 2.0 * inner + 1e-3);
        /* and the same across the top and bottom rows (v = 1 meets v = 0) */
        double vs = 0, vin = 0;
        for (uint32_t x = 0; x < w; x++) {
            vs += fabs(h[x] - h[(size_t)(rows - 1) * w + x]);
            for (uint32_t r = 0; r + 1 < rows; r++) vin += fabs(h[(size_t)r * w + x] - h[(size_t)(r + 1) * w + x]);
        }
        CHECK(vs / w <= 2.0 * vin / ((double)w * (rows - 1)) + 1e-3);
        /* a pattern, not a flat field: furrows and plates both present */
        uint32_t low = 0, high = 0;
        for (uint32_t i = 0; i < w * rows; i++) low += h[i] < 0.5f, high += h[i] > 0.99f;
        CHECK(low > w * rows / 200 && high > w * rows / 4);
        free(h);
    }
}

TEST(albedo_luminance_rises_with_height)
{
    /* the renderer's bark bump reads luminance as height, so a higher texel never looks darker */
    bark_fractal_params p = bark_fractal_preset_params(BARK_FRACTAL_FURROWED);
    p.furrow[0] = 0.10, p.furrow[1] = 0.08, p.furrow[2] = 0.05;
    p.plate[0] = 0.55, p.plate[1] = 0.45, p.plate[2] = 0.35;
    enum { N = 64 };
    float h[N];
    uint8_t c[N * 4];
    for (int i = 0; i < N; i++) h[i] = (float)i / (N - 1);
    bark_fractal_albedo(&p, N, 1, h, c);
    for (int i = 1; i < N; i++) {
        CHECK(c[4 * i] >= c[4 * (i - 1)] && c[4 * i + 1] >= c[4 * (i - 1) + 1] && c[4 * i + 2] >= c[4 * (i - 1) + 2]);
        CHECK_INT(c[4 * i + 3], 255);
    }
    /* the ends are the palette, sRGB-encoded: 0.10 linear is 89, 0.55 is 196 */
    CHECK_INT(c[0], 89);
    CHECK_INT(c[4 * (N - 1)], 196);
}

TEST(normals_follow_the_height_gradient_and_wrap)
{
    enum { W = 8, H = 4 };
    float h[W * H];
    uint8_t n[W * H * 4];
    for (int i = 0; i < W * H; i++) h[i] = 0.3f;
    bark_fractal_normals(W, H, h, 2.0, n);
    for (int i = 0; i < W * H; i++) CHECK(n[4 * i] == 128 && n[4 * i + 1] == 128 && n[4 * i + 2] == 255);
    /* one raised column at x = 0: its neighbours, x = 1 and across the seam x = W - 1, tilt away */
    for (int r = 0; r < H; r++) h[r * W] = 0.8f;
    bark_fractal_normals(W, H, h, 2.0, n);
    for (int r = 0; r < H; r++) {
        CHECK(n[4 * (r * W + 1)] > 128);     /* x = 1: height falls toward +u, normal leans +u */
        CHECK(n[4 * (r * W + W - 1)] < 128); /* x = W - 1: rises toward +u across the seam */
        CHECK_INT(n[4 * (r * W)], 128);      /* the ridge itself is level along u */
        CHECK_INT(n[4 * (r * W + 1) + 1], 128);
    }
}

TEST(bad_parameters_are_refused_with_a_sentence)
{
    char msg[200];
    bark_fractal_params p = bark_fractal_preset_params(BARK_FRACTAL_SCALY);
    CHECK_INT(bark_fractal_check(&p, msg, sizeof msg), 0);
    p.iterations = 0;
    CHECK_INT(bark_fractal_check(&p, msg, sizeof msg), -1);
    CHECK_STR_CONTAINS(msg, "iterations 0: must be 1 .. 4096");
    p = bark_fractal_preset_params(BARK_FRACTAL_SCALY);
    p.radius_outer = p.radius_inner;
    CHECK_INT(bark_fractal_check(&p, msg, sizeof msg), -1);
    CHECK_STR_CONTAINS(msg, "need 0 <= inner < outer");
    p = bark_fractal_preset_params(BARK_FRACTAL_SCALY);
    p.plate[1] = NAN;
    CHECK_INT(bark_fractal_check(&p, msg, sizeof msg), -1);
    CHECK_STR_CONTAINS(msg, "palette channel 1");
    p = bark_fractal_preset_params(BARK_FRACTAL_SCALY);
    p.crack_width = 0;
    CHECK_INT(bark_fractal_check(&p, msg, sizeof msg), -1);
    CHECK_STR_CONTAINS(msg, "crack_width 0");
    p = bark_fractal_preset_params(BARK_FRACTAL_SCALY);
    p.theta = INFINITY;
    CHECK_INT(bark_fractal_check(&p, msg, sizeof msg), -1);
    CHECK_STR_CONTAINS(msg, "theta inf");
}

TEST_LIST(TEST_CASE(spot_values_follow_hand_worked_orbits),
          TEST_CASE(counts_match_an_independent_reference_over_the_plane),
          TEST_CASE(smooth_count_and_distance_agree_with_the_count), TEST_CASE(textures_are_deterministic),
          TEST_CASE(pattern_closes_round_the_branch), TEST_CASE(albedo_luminance_rises_with_height),
          TEST_CASE(normals_follow_the_height_gradient_and_wrap),
          TEST_CASE(bad_parameters_are_refused_with_a_sentence))
