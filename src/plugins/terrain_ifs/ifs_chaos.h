/* ifs_chaos.h — random iteration of the IFS (Petric 1994, Fig. 1; MODELS.md §1): from a
 * starting point, NK times pick a map w_{n,m} with probability R_{n,m}, apply it and record the
 * point; the points are accumulated onto an output grid as the mean height of the points
 * nearest each node, and nodes no point reached take the deterministic evaluation.
 *
 * Determinism: the NK points are cut into chains of IFS_CHAIN_POINTS; chain c starts afresh at
 * the starting point and draws from its own stream (streams[c]), so every point is fixed by
 * the seed alone. Heights are summed as 64-bit fixed-point integers (z_bound / 2^31 m each),
 * so the sums are exact and their order — hence the thread count — does not matter.
 */
#ifndef TERRAIN_IFS_CHAOS_H
#define TERRAIN_IFS_CHAOS_H

#include <stdint.h>

#include "plugin_err.h"
#include "ifs_eval.h"
#include "ifs_maps.h"
#include "plugin_threads.h"
#include "sylva/plugin.h"

#define IFS_CHAIN_POINTS (1u << 20) /* points per chain */
#define IFS_MAX_POINTS 1000000000ull /* NK limit: at 20 M points/s, under a minute per core */

typedef struct ifs_chaos_job {
    uint64_t points;          /* NK, 1 .. IFS_MAX_POINTS */
    double start_u, start_v;  /* starting point in unit coordinates, inside [0, 1]^2 */
    double start_z;           /* starting height, metres */
    const sylva_rng *streams; /* ifs_chaos_chain_count(points) streams, chain c uses streams[c] */
    uint64_t (*rng_u64)(sylva_rng *); /* draws from a stream (e.g. api->rng_u64) */
    uint32_t nx, ny;          /* output nodes, >= 2 each, spanning the DTM footprint */
    ifs_window window;        /* the nodes written (points nearest other nodes are dropped);
                                 all zero: the whole grid */
    uint32_t depth;           /* depth of the deterministic evaluation for nodes no point reached */
    uint32_t threads;         /* workers, 1 .. PLUGIN_MAX_THREADS */
    plugin_progress_fn progress; /* may be NULL; called on the calling thread */
    void *pctx;
} ifs_chaos_job;

typedef struct ifs_chaos_stats {
    uint64_t empty_nodes;     /* output nodes no point reached (filled by evaluation) */
    uint32_t workers;         /* threads that ran */
} ifs_chaos_stats;

uint64_t ifs_chaos_chain_count(uint64_t points);

/* Runs the random iteration and writes the window's nx * ny heights (row 0 south) into z; each
 * node gets the same number as when the whole grid is made. Fails when NK is 0
 * or above IFS_MAX_POINTS, the start lies outside the footprint or beyond the heights the maps
 * reach (|z| > z_bound), or memory runs out (every worker needs 16 bytes per output node).
 * stats may be NULL. */
int ifs_chaos_grid(const ifs_maps *m, const ifs_chaos_job *job, float *z, ifs_chaos_stats *stats,
                   plugin_err *err);

/* The first n points of one chain from (u, v, z), as (U, V, z) triples in uvz (3n doubles):
 * the points ifs_chaos_grid accumulates, for tests and plots. */
void ifs_chaos_points(const ifs_maps *m, double u, double v, double z, sylva_rng *stream,
                      uint64_t (*rng_u64)(sylva_rng *), uint64_t n, double *uvz);

#endif
