/* pixel_strata.h — where in its pixel each of a pixel's n camera samples falls: correlated
 * multi-jittered positions (Kensler, "Correlated Multi-Jittered Sampling", Pixar technical memo
 * 13-01, 2013). The n samples fill an m x k grid of cells (m k >= n, m about sqrt(n)) one each,
 * and their x and y projections fall one in each of n equal strips, so an edge or a shadow
 * boundary across the pixel is integrated far better than by independent positions, while
 * every position is still uniform over the pixel (the mean is unchanged). The grid's rows and
 * columns are shuffled per pixel by a pattern key, so neighbouring pixels do not repeat one
 * arrangement.
 * Pure functions of (sample, n, pattern): deterministic for any thread count. */
#ifndef SYLVA_PIXEL_STRATA_H
#define SYLVA_PIXEL_STRATA_H

#include <math.h>
#include <stdint.h>

#include "util/rng.h"

/* A permutation of [0, len) chosen by key: a bijection of the next power of two (odd multiply,
 * add, xor-shift, all invertible modulo 2^bits), walked until it lands inside [0, len). */
static inline uint32_t strata_permute(uint32_t i, uint32_t len, uint64_t key)
{
    if (len <= 1) return 0;
    uint32_t bits = 32 - (uint32_t)__builtin_clz(len - 1), mask = bits >= 32 ? ~0u : (1u << bits) - 1;
    uint32_t mul = (uint32_t)(key >> 32) | 1u, add = (uint32_t)key;
    do {
        for (int r = 0; r < 3; r++) {
            i = (i * mul + add) & mask;
            i ^= (i >> ((bits + 1) / 2)) & mask;
            mul = mul * 0x2c1b3c6du | 1u, add = add * 0x297a2d39u + 0x9e3779b9u;
        }
        mul = (uint32_t)(key >> 32) | 1u, add = (uint32_t)key;
    } while (i >= len);
    return i;
}

/* The position in [0, 1)^2 of sample s of n in the pixel with pattern key `pattern`. */
static inline void strata_position(uint32_t s, uint32_t n, uint64_t pattern, float *x, float *y)
{
    uint32_t m = (uint32_t)floor(sqrt((double)n) + 0.5), k = (n + m - 1) / m;
    s = strata_permute(s, n, rng_combine(pattern, 1));
    uint32_t col = s % m, row = s / m;
    /* one shuffle of the columns and one of the rows for all samples (the "correlated" choice):
     * distinct cells keep distinct x strips */
    uint32_t sx = strata_permute(col, m, rng_combine(pattern, 2)), sy = strata_permute(row, k, rng_combine(pattern, 3));
    float jx = rng_u01f(rng_combine(pattern, 4000037u + s)), jy = rng_u01f(rng_combine(pattern, 8000009u + s));
    *x = ((float)sx + ((float)sy + jx) / (float)k) / (float)m;
    *y = ((float)s + jy) / (float)n;
    if (*x >= 1.0f) *x = 0x1.fffffep-1f;
    if (*y >= 1.0f) *y = 0x1.fffffep-1f;
}

#endif
