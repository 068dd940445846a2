/* seeded_dtm.h — a test DTM made by the plugin's own generator (dtm_generate.h) from a seed:
 * n x n nodes `spacing` metres apart, `relief` metres from lowest to highest, Hurst exponent
 * `hurst`. Header-only, for the terrain_ifs test executables (after harness.h). */
#ifndef SYLVA_TEST_SEEDED_DTM_H
#define SYLVA_TEST_SEEDED_DTM_H

#include "dtm_generate.h"
#include "util/rng.h"

static inline uint64_t seeded_dtm_next(sylva_rng *r) { return rng_next_u64(r); }

/* A new DTM (caller frees with ifs_dtm_free), or NULL after a failed CHECK. */
static inline ifs_dtm *seeded_dtm(uint32_t n, double spacing, double relief, double hurst, uint64_t seed)
{
    ifs_dtm_generator g = {.nx = n, .ny = n, .dx = spacing, .dy = spacing, .relief = relief, .smoothness = hurst};
    sylva_rng rng;
    rng_stream(&rng, seed, "terrain_ifs.dtm", 0);
    ifs_dtm *d = NULL;
    plugin_err err = {0};
    CHECK(ifs_dtm_generate(&g, seeded_dtm_next, &rng, &d, &err) == 0);
    return d;
}

#endif
