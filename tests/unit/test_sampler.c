/* test_sampler.c — the path tracer's sample values (render/sampler.h): keyed, uniform,
 * stratified in one and two dimensions for every power-of-two prefix, and different dimensions
 * not correlated with each other. */
#include "harness.h"

#include "render/sampler.h"

TEST(keyed_and_uniform)
{
    sampler a, b;
    sampler_start(&a, 1, 100, 3);
    sampler_start(&b, 1, 100, 3);
    for (uint32_t d = 0; d < 64; d++) CHECK(sampler_1d(&a, d) == sampler_1d(&b, d));
    sampler_start(&b, 1, 101, 3);
    int same = 0;
    for (uint32_t d = 0; d < 64; d++) same += sampler_1d(&a, d) == sampler_1d(&b, d);
    CHECK(same < 2);
    sampler_start(&b, 2, 100, 3);
    same = 0;
    for (uint32_t d = 0; d < 64; d++) same += sampler_1d(&a, d) == sampler_1d(&b, d);
    CHECK(same < 2);
    /* mean and variance of one sample's value over many pixels, in 1-D and 2-D */
    double sum = 0, sq = 0, su = 0, sv = 0, suv = 0;
    int n = 200000;
    for (int i = 0; i < n; i++) {
        sampler s;
        sampler_start(&s, 9, (uint64_t)i, 5);
        float x = sampler_1d(&s, 5), u, v;
        sampler_2d(&s, 6, &u, &v);
        CHECK(x >= 0.0f && x < 1.0f && u >= 0.0f && u < 1.0f && v >= 0.0f && v < 1.0f);
        sum += x, sq += x * x, su += u, sv += v, suv += u * v;
    }
    CHECK_NEAR(sum / n, 0.5, 0.005);
    CHECK_NEAR(sq / n - (sum / n) * (sum / n), 1.0 / 12.0, 0.002);
    CHECK_NEAR(su / n, 0.5, 0.005);
    CHECK_NEAR(sv / n, 0.5, 0.005);
    CHECK_NEAR(suv / n - (su / n) * (sv / n), 0.0, 0.002);
}

/* The first 2^k samples of a pair, for k up to 10, put exactly one point in every elementary
 * interval [a / 2^i, (a + 1) / 2^i) x [b / 2^j, (b + 1) / 2^j) with i + j = k: a (0,k,2)-net,
 * in every pixel and every pair. Independent values fail this from k = 1 on. */
TEST(pairs_are_nets_for_every_power_of_two)
{
    static uint8_t count[1024];
    static float u[1024], v[1024];
    int bad = 0;
    for (uint64_t pixel = 0; pixel < 12; pixel++)
        for (uint32_t d = 0; d < 40; d += 2 + (uint32_t)pixel % 3) {
            sampler s;
            for (uint32_t i = 0; i < 1024; i++) {
                sampler_start(&s, 77, pixel * 7919, i);
                sampler_2d(&s, d, &u[i], &v[i]);
            }
            for (uint32_t k = 0; k <= 10; k++)
                for (uint32_t ix = 0; ix <= k; ix++) {
                    uint32_t nx = 1u << ix, ny = 1u << (k - ix), n = 1u << k;
                    memset(count, 0, n);
                    for (uint32_t i = 0; i < n; i++) {
                        uint32_t cx = (uint32_t)(u[i] * (float)nx), cy = (uint32_t)(v[i] * (float)ny);
                        count[cy * nx + cx]++;
                    }
                    for (uint32_t c = 0; c < n; c++) bad += count[c] != 1;
                }
        }
    CHECK_INT(bad, 0);
}

/* The first 2^k samples of a single dimension fall one in each of 2^k equal strips. */
TEST(single_dimensions_are_stratified)
{
    static uint8_t count[4096];
    int bad = 0;
    for (uint64_t pixel = 0; pixel < 8; pixel++)
        for (uint32_t d = 0; d < 30; d += 3) {
            float x[4096];
            for (uint32_t i = 0; i < 4096; i++) {
                sampler s;
                sampler_start(&s, 3, pixel, i);
                x[i] = sampler_1d(&s, d);
            }
            for (uint32_t k = 0; k <= 12; k++) {
                uint32_t n = 1u << k;
                memset(count, 0, n);
                for (uint32_t i = 0; i < n; i++) count[(uint32_t)(x[i] * (float)n)]++;
                for (uint32_t c = 0; c < n; c++) bad += count[c] != 1;
            }
        }
    CHECK_INT(bad, 0);
}

/* Different pairs of one pixel take their points in unrelated orders: over 1024 samples the
 * correlation of dimension 0 with 2, 4, ... stays within chance (|r| about 1 / sqrt(1024)).
 * Without the index shuffle every pair would repeat the same sequence (r = 1). */
TEST(dimensions_are_not_correlated)
{
    const uint32_t n = 1024;
    double worst = 0;
    for (uint64_t pixel = 0; pixel < 4; pixel++)
        for (uint32_t d = 2; d < 24; d += 2) {
            double s0 = 0, s1 = 0, s00 = 0, s11 = 0, s01 = 0;
            for (uint32_t i = 0; i < n; i++) {
                sampler s;
                sampler_start(&s, 11, pixel, i);
                float a, b, c, e;
                sampler_2d(&s, 0, &a, &b);
                sampler_2d(&s, d, &c, &e);
                s0 += a, s1 += c, s00 += a * a, s11 += c * c, s01 += a * c;
            }
            double cov = s01 / n - s0 / n * s1 / n;
            double r = cov / sqrt((s00 / n - s0 / n * s0 / n) * (s11 / n - s1 / n * s1 / n));
            worst = fmax(worst, fabs(r));
        }
    fprintf(stderr, "  largest |correlation| between pairs: %.4f\n", worst);
    CHECK(worst < 0.15);
}

/* Owen scrambling is a bijection of the 32-bit values that keeps every aligned block of 2^k
 * values an aligned block (here: of 2^8 and 2^16 values, both ends of the range). */
TEST(owen_scrambling_keeps_blocks)
{
    static uint8_t seen[1u << 16];
    const uint64_t seeds[3] = {0, 0x9e3779b97f4a7c15ull, 12345};
    for (int t = 0; t < 3; t++)
        for (uint32_t base = 0; base < 2; base++) {
            uint32_t start = base ? 0xffff0000u : 0u, first = sampler_owen(start, seeds[t]) & 0xffff0000u;
            int bad = 0;
            memset(seen, 0, sizeof seen);
            for (uint32_t i = 0; i < (1u << 16); i++) {
                uint32_t y = sampler_owen(start + i, seeds[t]);
                bad += (y & 0xffff0000u) != first || seen[y & 0xffffu]++;
                uint32_t block = sampler_owen((start + i) & ~0xffu, seeds[t]) & ~0xffu;
                bad += (y & ~0xffu) != block;
            }
            CHECK_INT(bad, 0);
        }
}

TEST_LIST(TEST_CASE(keyed_and_uniform), TEST_CASE(pairs_are_nets_for_every_power_of_two),
          TEST_CASE(single_dimensions_are_stratified), TEST_CASE(dimensions_are_not_correlated),
          TEST_CASE(owen_scrambling_keeps_blocks))
