/* ifs_chaos.c — the random iteration ("chaos game") and its accumulation onto a grid. */
#include "ifs_chaos.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ifs_eval.h"

/* Point sums of one output node: fixed-point height sum and point count. */
typedef struct node_sum {
    int64_t sum;
    uint32_t count;
    uint32_t pad;
} node_sum;

typedef struct chaos_run {
    const ifs_maps *m;
    const ifs_chaos_job *job;
    node_sum **acc;   /* one grid per worker, over the window */
    ifs_window window;
    double quantum_per_metre;
} chaos_run;

/* Scaled heights lie in [-2^31, 2^31]: adding 2^31 + 1/2 makes them positive, so truncation
 * rounds to the nearest quantum; the 2^31 is taken off again as an integer. */
#define FIXED_SHIFT 2147483648.0
#define FIXED_SHIFT_ROUNDING (FIXED_SHIFT + 0.5)

/* One step of the iteration: w_{n,m} (12) applied to (u, v, z). */
static inline void chaos_step(const ifs_maps *m, uint64_t r, double *u, double *v, double *z)
{
    ifs_map map = ifs_maps_cell(m, ifs_maps_pick(m, r));
    const ifs_map *w = &map;
    double uu = *u, vv = *v;
    *z = w->c0 + w->cu * uu + w->cv * vv + w->cuv * uu * vv + w->alpha * *z;
    *u = w->u0 + uu * m->su;
    *v = w->v0 + vv * m->sv;
}

uint64_t ifs_chaos_chain_count(uint64_t points)
{
    return (points + IFS_CHAIN_POINTS - 1) / IFS_CHAIN_POINTS;
}

void ifs_chaos_points(const ifs_maps *m, double u, double v, double z, sylva_rng *stream,
                      uint64_t (*rng_u64)(sylva_rng *), uint64_t n, double *uvz)
{
    for (uint64_t k = 0; k < n; k++) {
        chaos_step(m, rng_u64(stream), &u, &v, &z);
        uvz[3 * k] = u, uvz[3 * k + 1] = v, uvz[3 * k + 2] = z;
    }
}

/* Points wait this many steps between computing their node and adding to it, so that the
 * node's cache line is prefetched while the next points are computed (the nodes a random
 * iteration visits are scattered over the whole grid). */
#define CHAOS_PENDING 16u

static void chaos_chain(void *ctx, uint32_t worker, uint64_t chain)
{
    const chaos_run *run = ctx;
    const ifs_chaos_job *job = run->job;
    const ifs_maps *m = run->m;
    node_sum *acc = run->acc[worker];
    uint64_t first = chain * IFS_CHAIN_POINTS;
    uint64_t n = job->points - first < IFS_CHAIN_POINTS ? job->points - first : IFS_CHAIN_POINTS;
    sylva_rng stream = job->streams[chain];
    uint64_t (*next)(sylva_rng *) = job->rng_u64;
    double u = job->start_u, v = job->start_v, z = job->start_z;
    double fx = job->nx - 1, fy = job->ny - 1, q = run->quantum_per_metre;
    uint32_t imax = job->nx - 1, jmax = job->ny - 1;
    const ifs_window *w = &run->window;
    size_t pending_node[CHAOS_PENDING];
    int64_t pending_q[CHAOS_PENDING];
    for (uint64_t k = 0; k < n; k++) {
        chaos_step(m, next(&stream), &u, &v, &z);
        uint32_t i = (uint32_t)(u * fx + 0.5), j = (uint32_t)(v * fy + 0.5);
        if (i > imax) i = imax;
        if (j > jmax) j = jmax;
        /* outside the window: the node's slot-free sentinel, never added */
        size_t node = i - w->i0 < w->nx && j - w->j0 < w->ny
                          ? (size_t)(j - w->j0) * w->nx + (i - w->i0) : SIZE_MAX;
        if (node != SIZE_MAX) __builtin_prefetch(&acc[node], 1);
        uint32_t slot = (uint32_t)(k % CHAOS_PENDING);
        if (k >= CHAOS_PENDING && pending_node[slot] != SIZE_MAX) {
            acc[pending_node[slot]].sum += pending_q[slot];
            acc[pending_node[slot]].count++;
        }
        pending_node[slot] = node;
        pending_q[slot] = (int64_t)(z * q + FIXED_SHIFT_ROUNDING) - (int64_t)FIXED_SHIFT;
    }
    for (uint64_t k = n > CHAOS_PENDING ? n - CHAOS_PENDING : 0; k < n; k++) {
        uint32_t slot = (uint32_t)(k % CHAOS_PENDING);
        if (pending_node[slot] == SIZE_MAX) continue;
        acc[pending_node[slot]].sum += pending_q[slot];
        acc[pending_node[slot]].count++;
    }
}

typedef struct merge_run {
    const ifs_maps *m;
    const ifs_chaos_job *job;
    node_sum **acc;
    uint32_t workers;
    ifs_window window;
    double metres_per_quantum;
    float *z;
    uint64_t *empty_per_row;
} merge_run;

/* Row j of the output: the workers' sums added (integers: order-free), the mean taken, empty
 * nodes evaluated. */
static void merge_row(void *ctx, uint32_t worker, uint64_t row)
{
    const merge_run *mr = ctx;
    const ifs_chaos_job *job = mr->job;
    const ifs_window *w = &mr->window;
    uint32_t j = w->j0 + (uint32_t)row;
    size_t base = (size_t)row * w->nx;
    uint64_t empty = 0;
    for (uint32_t k = 0; k < w->nx; k++) {
        uint32_t i = w->i0 + k;
        int64_t sum = 0;
        uint64_t count = 0;
        for (uint32_t t = 0; t < mr->workers; t++) {
            sum += mr->acc[t][base + k].sum;
            count += mr->acc[t][base + k].count;
        }
        if (count) {
            mr->z[base + k] = (float)((double)sum / (double)count * mr->metres_per_quantum);
        } else {
            double sx = (double)i * mr->m->ncx / (job->nx - 1);
            double sy = (double)j * mr->m->ncy / (job->ny - 1);
            mr->z[base + k] = (float)ifs_eval_at(mr->m, sx, sy, job->depth);
            empty++;
        }
    }
    mr->empty_per_row[row] = empty;
}

int ifs_chaos_grid(const ifs_maps *m, const ifs_chaos_job *job, float *z, ifs_chaos_stats *stats,
                   plugin_err *err)
{
    if (job->points < 1 || job->points > IFS_MAX_POINTS)
        return plugin_fail(err, SYLVA_ERR_LIMIT,
                        "%llu iterations (NK) asked for; the random iteration runs 1 to %llu",
                        (unsigned long long)job->points, IFS_MAX_POINTS);
    if (job->nx < 2 || job->ny < 2)
        return plugin_fail(err, SYLVA_ERR_PARAM,
                        "an output grid of %u x %u nodes is too small; it needs 2 x 2 at least",
                        job->nx, job->ny);
    if (!(job->start_u >= 0 && job->start_u <= 1 && job->start_v >= 0 && job->start_v <= 1) ||
        !isfinite(job->start_z))
        return plugin_fail(err, SYLVA_ERR_PARAM,
                        "the starting point (%g, %g) of the DTM's unit square, height %g, is "
                        "outside the DTM; it must lie on its footprint", job->start_u,
                        job->start_v, job->start_z);
    if (fabs(job->start_z) > m->z_bound)
        return plugin_fail(err, SYLVA_ERR_PARAM,
                        "the starting height %g m lies outside the heights the maps can reach "
                        "(-%g to %g m); start near the DTM's surface", job->start_z, m->z_bound,
                        m->z_bound);
    ifs_window win = job->window;
    if (!win.nx && !win.ny) win = (ifs_window){0, 0, job->nx, job->ny};
    if (!win.nx || !win.ny || win.i0 + (uint64_t)win.nx > job->nx || win.j0 + (uint64_t)win.ny > job->ny)
        return plugin_fail(err, SYLVA_ERR_PARAM, "the window of %u x %u nodes from node (%u, %u) does "
                        "not lie inside the %u x %u output grid", win.nx, win.ny, win.i0, win.j0,
                        job->nx, job->ny);
    uint64_t chains = ifs_chaos_chain_count(job->points);
    uint32_t workers = job->threads < 1 ? 1 : job->threads;
    if (workers > PLUGIN_MAX_THREADS) workers = PLUGIN_MAX_THREADS;
    if (workers > chains) workers = (uint32_t)chains;
    size_t nodes = (size_t)win.nx * win.ny;
    node_sum *acc[PLUGIN_MAX_THREADS] = {0}; /* owned here, one grid per worker */
    uint64_t *empty_per_row = malloc((size_t)win.ny * sizeof *empty_per_row);
    int rc = SYLVA_OK;
    if (!empty_per_row) {
        rc = plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for a %u-row output grid", job->ny);
        goto done;
    }
    for (uint32_t w = 0; w < workers; w++) {
        acc[w] = calloc(nodes, sizeof(node_sum));
        if (!acc[w]) {
            if (w == 0) {
                rc = plugin_fail(err, SYLVA_ERR_NOMEM,
                              "out of memory for the point sums of a %u x %u output grid",
                              job->nx, job->ny);
                goto done;
            }
            workers = w; /* fewer workers, same result */
            break;
        }
    }
    /* Every |z| reached stays below z_bound: 2^31 quanta cover it, so sums of up to
     * IFS_MAX_POINTS < 2^32 points fit in 63 bits. */
    double quantum_per_metre = m->z_bound > 0 ? 2147483647.0 / m->z_bound : 1.0;
    chaos_run run = {.m = m, .job = job, .acc = acc, .window = win,
                     .quantum_per_metre = quantum_per_metre};
    uint32_t ran = plugin_threads_run(workers, chains, chaos_chain, &run, job->progress, job->pctx);
    merge_run mr = {.m = m, .job = job, .acc = acc, .workers = workers, .window = win,
                    .metres_per_quantum = 1.0 / quantum_per_metre, .z = z,
                    .empty_per_row = empty_per_row};
    plugin_threads_run(workers, win.ny, merge_row, &mr, NULL, NULL);
    if (stats) {
        stats->empty_nodes = 0;
        for (uint32_t j = 0; j < win.ny; j++) stats->empty_nodes += empty_per_row[j];
        stats->workers = ran;
    }
done:
    for (uint32_t w = 0; w < PLUGIN_MAX_THREADS; w++) free(acc[w]);
    free(empty_per_row);
    return rc;
}
