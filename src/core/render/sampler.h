/* sampler.h — random numbers for rendering, keyed by (seed, pixel, sample index, dimension):
 * a pixel's samples are the same whichever thread renders it and in whatever order, so images
 * are bit-identical for any thread count. Dimensions are laid out by the integrator. */
#ifndef SYLVA_SAMPLER_H
#define SYLVA_SAMPLER_H

#include <stdint.h>

#include "util/rng.h"

typedef struct sampler {
    uint64_t key;    /* hash of (seed, pixel, sample) */
    uint32_t dim;    /* next dimension */
} sampler;

static inline void sampler_start(sampler *s, uint64_t seed, uint64_t pixel, uint32_t sample)
{
    s->key = rng_combine(rng_combine(seed, pixel), sample);
    s->dim = 0;
}

/* The value for dimension d, uniform in [0, 1). */
static inline float sampler_at(const sampler *s, uint32_t d) { return rng_u01f(s->key ^ ((uint64_t)d << 40 | d)); }

static inline float sampler_next(sampler *s) { return sampler_at(s, s->dim++); }

#endif
