/* rng.h — counter-based randomness. Every random number in sylva is a hash of what it is for
 * (seed, purpose, index, counter), never state shared between threads, so results do not depend
 * on thread count or order of work. */
#ifndef SYLVA_RNG_H
#define SYLVA_RNG_H

#include <stdint.h>

#include "sylva/plugin.h"

/* A strong 64-bit finaliser (splitmix64 / Stafford's mix13). */
static inline uint64_t rng_mix64(uint64_t z)
{
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

static inline uint64_t rng_combine(uint64_t a, uint64_t b) { return rng_mix64(a ^ rng_mix64(b)); }

/* FNV-1a of a purpose string, mixed. */
static inline uint64_t rng_hash_str(const char *s)
{
    uint64_t h = 0xcbf29ce484222325ull;
    while (s && *s) h = (h ^ (uint8_t)*s++) * 0x100000001b3ull;
    return rng_mix64(h);
}

static inline void rng_stream(sylva_rng *r, uint64_t seed, const char *purpose, uint64_t index)
{
    r->key = rng_combine(rng_combine(seed, rng_hash_str(purpose)), index);
    r->counter = 0;
}

static inline uint64_t rng_next_u64(sylva_rng *r) { return rng_combine(r->key, r->counter++); }

/* [0, 1) with 53 bits. */
static inline double rng_next_double(sylva_rng *r)
{
    return (double)(rng_next_u64(r) >> 11) * (1.0 / 9007199254740992.0);
}

/* [0, 1) float with 24 bits, from a key alone. */
static inline float rng_u01f(uint64_t key) { return (float)(rng_mix64(key) >> 40) * (1.0f / 16777216.0f); }

#endif
