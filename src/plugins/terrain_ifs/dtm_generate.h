/* dtm_generate.h — a coarse DTM made up from the scene seed, for scenes without surveyed data:
 * midpoint displacement (the diamond-square scheme) on a 2^k + 1 grid, the requested block of
 * it, heights rescaled to [0, relief]. The IFS then adds the fine roughness, exactly as it would
 * to a surveyed DTM.
 *
 * Random numbers come only from the stream handed in (the plugin passes a host stream keyed by
 * the scene seed and the purpose "terrain_ifs.dtm"), drawn in a fixed order. */
#ifndef TERRAIN_IFS_DTM_GENERATE_H
#define TERRAIN_IFS_DTM_GENERATE_H

#include <stdint.h>

#include "dtm.h"
#include "plugin_err.h"
#include "sylva/plugin.h"

#define IFS_GENERATED_MAX_SIDE 1025u

typedef struct ifs_dtm_generator {
    uint32_t nx, ny;    /* nodes, IFS_DTM_MIN_SIDE .. IFS_GENERATED_MAX_SIDE each */
    double dx, dy;      /* node spacing, metres */
    double relief;      /* height difference between the lowest and highest node, metres (>= 0) */
    double smoothness;  /* Hurst exponent H in (0, 1]: displacements shrink by 2^-H per halving */
} ifs_dtm_generator;

/* rng_u64 draws from *rng (e.g. api->rng_u64). */
int ifs_dtm_generate(const ifs_dtm_generator *g, uint64_t (*rng_u64)(sylva_rng *), sylva_rng *rng,
                     ifs_dtm **out, plugin_err *err);

#endif
