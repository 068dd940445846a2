/* sampler.h — the path tracer's sample values: an Owen-scrambled Sobol sequence, shuffled per
 * pixel and per dimension (Burley 2020, "Practical Hash-based Owen Scrambling", JCGT 9(4)),
 * keyed by (seed, pixel, sample index, dimension). A pixel's samples are the same whichever
 * thread renders it and in whatever order, so images are bit-identical for any thread count.
 *
 * Dimensions come one at a time (sampler_1d) or in pairs (sampler_2d, dimensions d and d + 1);
 * the integrator lays them out. A pair is the first two Sobol dimensions, a (0,2)-sequence in
 * base 2: every aligned block of 2^k indices holds one point in each of the 2^k elementary
 * intervals of each shape (2^a x 2^b cells, a + b = k). A single dimension is the first (the
 * van der Corput sequence): 2^k indices fall one in each of 2^k equal strips. Two things make
 * that stratification every pixel's own while keeping it:
 * - Owen scrambling of each value (a random flip of every binary digit chosen by the digits
 *   before it), by a hash in which bit j depends on bits below it alone, applied to the value's
 *   bits reversed. It keeps nets nets and makes every value uniform in [0, 1).
 * - The same scrambling of the sample index, with a key of the dimension's own, which shuffles
 *   the sequence's order: indices 0 .. 2^k - 1 land on one aligned block of 2^k indices, so the
 *   first 2^k samples keep their stratification, while different dimensions (and pairs) see
 *   their points in unrelated orders and are not correlated with each other ("padding").
 * Sample counts need not be powers of two; those are where the strata are complete. */
#ifndef SYLVA_SAMPLER_H
#define SYLVA_SAMPLER_H

#include <stdint.h>

#include "util/rng.h"

typedef struct sampler {
    uint64_t key;    /* hash of (seed, pixel) */
    uint32_t index;  /* the sample's index in the pixel */
} sampler;

static inline void sampler_start(sampler *s, uint64_t seed, uint64_t pixel, uint32_t sample)
{
    s->key = rng_combine(seed, pixel);
    s->index = sample;
}

static inline uint32_t sampler_reverse_bits(uint32_t x)
{
    x = (x >> 16) | (x << 16);
    x = ((x & 0xff00ff00u) >> 8) | ((x & 0x00ff00ffu) << 8);
    x = ((x & 0xf0f0f0f0u) >> 4) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x & 0xccccccccu) >> 2) | ((x & 0x33333333u) << 2);
    return ((x & 0xaaaaaaaau) >> 1) | ((x & 0x55555555u) << 1);
}

/* Owen scrambling of x read as a binary fraction (bit 31 first), on its bits reversed: bit j of
 * r (bit 31 - j of x) is flipped by a function of the seed and of bits 0 .. j - 1 alone. Every
 * step keeps that: adding, multiplying by an odd number, and xoring with the product by an even
 * number. */
static inline uint32_t sampler_owen_reversed(uint32_t r, uint64_t seed)
{
    uint32_t lo = (uint32_t)seed, hi = (uint32_t)(seed >> 32);
    r += lo;
    r ^= r * 0x6a5d39eau;
    r *= hi | 1u;
    r ^= r * 0xb4f3c2d4u;
    r += hi;
    r ^= r * 0x3c8f71a6u;
    r *= 0x2c9277b5u ^ (lo & 0xfffffffeu);
    r ^= r * 0x8d2e6c58u;
    return r;
}

/* Owen scrambling of x (bit 31 first). */
static inline uint32_t sampler_owen(uint32_t x, uint64_t seed)
{
    return sampler_reverse_bits(sampler_owen_reversed(sampler_reverse_bits(x), seed));
}

/* The second Sobol dimension (primitive polynomial x + 1), its bits reversed: its generator
 * matrix is Pascal's triangle modulo 2, so by Lucas's theorem bit r of the reversed value is
 * the parity of the index's bits j with j & r == r, a sum over supersets that five shift-and-xor
 * steps compute. */
static inline uint32_t sampler_sobol1_reversed(uint32_t i)
{
    i ^= (i >> 1) & 0x55555555u;
    i ^= (i >> 2) & 0x33333333u;
    i ^= (i >> 4) & 0x0f0f0f0fu;
    i ^= (i >> 8) & 0x00ff00ffu;
    return i ^ ((i >> 16) & 0x0000ffffu);
}

static inline float sampler_float(uint32_t x) { return (float)(x >> 8) * (1.0f / 16777216.0f); }

/* The key of dimension d's index shuffle; its values' keys follow by mixing it again. */
static inline uint64_t sampler_key(const sampler *s, uint32_t d, uint32_t pair)
{
    return rng_mix64(s->key ^ ((uint64_t)(2 * d + pair) * 0x9e3779b97f4a7c15ull));
}

/* The value of dimension d, in [0, 1): the first Sobol dimension of the shuffled index is the
 * index's bits reversed, so its scrambling needs no reversal of its own. */
static inline float sampler_1d(const sampler *s, uint32_t d)
{
    uint64_t k = sampler_key(s, d, 0);
    uint32_t i = sampler_owen(s->index, k);
    return sampler_float(sampler_reverse_bits(sampler_owen_reversed(i, rng_mix64(k))));
}

/* The values of dimensions d and d + 1, a 2-D point in [0, 1)^2 (both Sobol dimensions are
 * scrambled in their reversed form). */
static inline void sampler_2d(const sampler *s, uint32_t d, float *u, float *v)
{
    uint64_t k = sampler_key(s, d, 1);
    uint32_t i = sampler_owen(s->index, k);
    uint64_t kx = rng_mix64(k), ky = rng_mix64(kx);
    *u = sampler_float(sampler_reverse_bits(sampler_owen_reversed(i, kx)));
    *v = sampler_float(sampler_reverse_bits(sampler_owen_reversed(sampler_sobol1_reversed(i), ky)));
}

#endif
