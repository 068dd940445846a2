/* terrain_ifs_throughput.c — speed of the terrain_ifs model: random iteration points per
 * second (goal: >= 20 M/s on one core), accumulated onto output grids of several sizes, and the
 * deterministic evaluation of a 2049 x 2049 grid from a 65 x 65 DTM (goal: <= 1 s on 2 cores).
 * Random numbers come through the host's own rng_u64, as in the plugin.
 *
 * usage: terrain_ifs_throughput [points]   (default 32 M points per measurement)
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "dtm_generate.h"
#include "ifs_chaos.h"
#include "ifs_eval.h"
#include "ifs_maps.h"
#include "scene_build/host.h"
#include "util/rng.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static void print_machine(void)
{
    char line[256], model[256] = "unknown";
    FILE *f = fopen("/proc/cpuinfo", "r");
    while (f && fgets(line, sizeof line, f))
        if (!strncmp(line, "model name", 10)) {
            char *c = strchr(line, ':');
            if (c) snprintf(model, sizeof model, "%s", c + 2);
            model[strcspn(model, "\n")] = 0;
            break;
        }
    if (f) fclose(f);
    printf("machine: %s, %u processors online\n", model, plugin_threads_online());
}

static ifs_maps *bench_maps(uint32_t n, double alpha, ifs_dtm **dtm_out)
{
    ifs_dtm_generator g = {.nx = n, .ny = n, .dx = 25, .dy = 25, .relief = 150, .smoothness = 0.8};
    sylva_rng rng;
    rng_stream(&rng, 1, "terrain_ifs.dtm", 0);
    plugin_err err = {0};
    ifs_dtm *d = NULL;
    ifs_maps *m = NULL;
    ifs_maps_params p = {.mode = IFS_MODE_BILINEAR, .alpha = alpha};
    if (ifs_dtm_generate(&g, host_api_table()->rng_u64, &rng, &d, &err) ||
        ifs_maps_build(d, &p, &m, &err)) {
        fprintf(stderr, "terrain_ifs_throughput: %s\n", err.msg);
        ifs_dtm_free(d);
        return NULL;
    }
    *dtm_out = d;
    return m;
}

/* Best of three runs of the random iteration; returns points per second. */
static double random_rate(const ifs_maps *m, const ifs_dtm *d, uint64_t points, uint32_t side,
                          uint32_t threads)
{
    uint64_t chains = ifs_chaos_chain_count(points);
    sylva_rng *streams = malloc(chains * sizeof *streams);
    float *z = malloc((size_t)side * side * sizeof *z);
    double best = 1e30;
    for (uint64_t c = 0; streams && c < chains; c++) rng_stream(&streams[c], 7, "terrain_ifs.chaos", c);
    ifs_chaos_job job = {.points = points, .start_z = d->z[0], .streams = streams,
                         .rng_u64 = host_api_table()->rng_u64, .nx = side, .ny = side, .depth = 1,
                         .threads = threads};
    for (int run = 0; streams && z && run < 3; run++) {
        plugin_err err = {0};
        double t0 = now();
        if (ifs_chaos_grid(m, &job, z, NULL, &err)) {
            fprintf(stderr, "terrain_ifs_throughput: %s\n", err.msg);
            break;
        }
        double t = now() - t0;
        if (t < best) best = t;
    }
    free(streams), free(z);
    return points / best;
}

static double eval_seconds(const ifs_maps *m, uint32_t side, uint32_t threads, uint32_t *depth)
{
    float *z = malloc((size_t)side * side * sizeof *z);
    *depth = ifs_eval_auto_depth(m, side, side);
    double best = 1e30;
    for (int run = 0; z && run < 3; run++) {
        plugin_err err = {0};
        double t0 = now();
        ifs_eval_grid(m, side, side, *depth, threads, z, NULL, NULL, &err);
        double t = now() - t0;
        if (t < best) best = t;
    }
    free(z);
    return best;
}

int main(int argc, char **argv)
{
    uint64_t points = argc > 1 ? strtoull(argv[1], NULL, 10) : 32ull << 20;
    if (points < 1 || points > IFS_MAX_POINTS) {
        fprintf(stderr, "usage: terrain_ifs_throughput [points, 1 to %llu]\n", IFS_MAX_POINTS);
        return 1;
    }
    print_machine();
    ifs_dtm *d = NULL;
    ifs_maps *m = bench_maps(65, 0.1, &d);
    if (!m) return 2;
    printf("\nrandom iteration, 65 x 65 DTM, alpha 0.1, %llu points per run (best of 3), goal >= 20 M points/s on one core\n",
           (unsigned long long)points);
    printf("  %-16s %14s %14s %10s\n", "output grid", "1 thread M/s", "2 threads M/s", "scaling");
    const uint32_t sides[] = {257, 513, 1025, 2049};
    for (size_t k = 0; k < sizeof sides / sizeof sides[0]; k++) {
        double r1 = random_rate(m, d, points, sides[k], 1), r2 = random_rate(m, d, points, sides[k], 2);
        printf("  %4u x %-9u %14.1f %14.1f %9.2fx\n", sides[k], sides[k], r1 / 1e6, r2 / 1e6, r2 / r1);
    }
    printf("\ndeterministic evaluation of 2049 x 2049 nodes from a 65 x 65 DTM, goal <= 1 s on 2 cores\n");
    printf("  %-7s %6s %12s %12s %10s\n", "alpha", "depth", "1 thread s", "2 threads s", "scaling");
    const double alphas[] = {0.1, 0.3, 0.5};
    for (size_t k = 0; k < sizeof alphas / sizeof alphas[0]; k++) {
        ifs_maps_free(m), ifs_dtm_free(d);
        m = bench_maps(65, alphas[k], &d);
        if (!m) return 2;
        uint32_t depth;
        double t1 = eval_seconds(m, 2049, 1, &depth), t2 = eval_seconds(m, 2049, 2, &depth);
        printf("  %-7.1f %6u %12.3f %12.3f %9.2fx\n", alphas[k], depth, t1, t2, t1 / t2);
    }
    ifs_maps_free(m);
    ifs_dtm_free(d);
    return 0;
}
