/* bench_scale.c — memory of a large forest through the whole render pipeline, per instance.
 *
 * N plants of 4 species x V age variants (the real models from their tree plugins,
 * bench_forest.h: the main job's species, or with --forest weber_penn four Weber-Penn species of
 * the species library) on a terrain sized to keep the density of bench_ecology's 1 M plants on
 * 2 km x 2 km, seen from beyond one corner so that most of them are distant crown proxies.
 * Each stage's resident memory over the species alone, divided by N: the plants as the ecology
 * hands them over, the scene's instance records, Embree's instances, the crown proxies, the
 * top BVH over both (built once, as the renderer does); then the real render (render_setup_new
 * and render_setup_run at a small size: BVH, lights, proxies and their calibration, pixels,
 * film) and the peak memory against the goal that 10 M plants render within 8 GB
 * (bench_forest_memory.h). One N per run, so the peak is that N's.
 *
 * --compare measures both forests, each at N and at N / 10 plants in a child process of its own,
 * and prints for each its peak and the bytes an instance adds apart from its prototype (the
 * peak's growth from N / 10 to N plants over the plants added), like with like: the same plant
 * counts, variants, terrain and picture.
 *
 * Usage: bench_scale [--plants N] [--threads N] [--size WxH] [--spp N] [--variants V]
 *                    [--forest main|weber_penn] [--compare]
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench_forest_memory.h"
#include "bench_machine.h"

#define GOAL_PLANTS 10e6
#define GOAL_MIB (8.0 * 1024)

typedef struct bench_args {
    uint32_t plants, w, h, spp, variants;
    unsigned threads;
    const bench_forest_plan *forest;
    int compare;
} bench_args;

static int run_one(const bench_args *a)
{
    err_buf err = {{0}};
    bench_forest_figures f;
    if (bench_forest_measure(a->forest, a->plants, a->variants, a->threads, a->w, a->h, a->spp, stdout, &f, &err))
        return fprintf(stderr, "bench: %s\n", err.msg), 4;
    double per = bench_per_plant(f.peak_mib - f.species_mib, f.plants);
    printf("  10 M plants at this rate: %.0f MiB (goal <= %.0f MiB)\n",
           f.species_mib + per * GOAL_PLANTS / (1024.0 * 1024.0), GOAL_MIB);
    return 0;
}

/* One forest at N / 10 and N plants; prints its line of the comparison. */
static int compare_one(const bench_args *a, const bench_forest_plan *plan, double *bytes)
{
    err_buf err = {{0}};
    bench_forest_figures small, large;
    uint32_t n0 = a->plants / 10 ? a->plants / 10 : 1;
    double t0 = progress_now();
    if (bench_forest_measure_apart(plan, n0, a->variants, a->threads, a->w, a->h, a->spp, stdout, &small, &err) ||
        bench_forest_measure_apart(plan, a->plants, a->variants, a->threads, a->w, a->h, a->spp, stdout, &large, &err))
        return fprintf(stderr, "bench: %s\n", err.msg), 4;
    *bytes = bench_forest_bytes_per_instance(&small, &large);
    printf("  => %s: %u prototypes, %llu triangles, species alone %.0f MiB; %u plants: peak %.0f MiB, %.0f B per "
           "plant over the species alone; %.1f B per instance (%u to %u plants); %.1f s for both runs\n\n",
           plan->name, large.prototypes, (unsigned long long)large.triangles, large.species_mib, large.plants,
           large.peak_mib, bench_per_plant(large.peak_mib - large.species_mib, large.plants), *bytes, small.plants,
           large.plants, progress_now() - t0);
    return 0;
}

static int run_compare(const bench_args *a)
{
    double main_bytes = 0, wp_bytes = 0;
    int rc = compare_one(a, &bench_forest_main, &main_bytes);
    if (!rc) rc = compare_one(a, &bench_forest_weber_penn, &wp_bytes);
    if (!rc)
        printf("bytes per instance: Weber-Penn %.1f, the main job's species %.1f (ratio %.3f)\n", wp_bytes, main_bytes,
               wp_bytes / main_bytes);
    return rc;
}

static int parse(int argc, char **argv, bench_args *a)
{
    for (int i = 1; i < argc; i++) {
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (v && !strcmp(argv[i], "--plants")) a->plants = (uint32_t)atol(argv[++i]);
        else if (v && !strcmp(argv[i], "--threads")) a->threads = (unsigned)atol(argv[++i]);
        else if (v && !strcmp(argv[i], "--spp")) a->spp = (uint32_t)atol(argv[++i]);
        else if (v && !strcmp(argv[i], "--variants")) a->variants = (uint32_t)atol(argv[++i]);
        else if (v && !strcmp(argv[i], "--size") && sscanf(v, "%ux%u", &a->w, &a->h) == 2) i++;
        else if (v && !strcmp(argv[i], "--forest") && (!strcmp(v, "main") || !strcmp(v, "weber_penn")))
            a->forest = !strcmp(argv[++i], "main") ? &bench_forest_main : &bench_forest_weber_penn;
        else if (!strcmp(argv[i], "--compare")) a->compare = 1;
        else return -1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    bench_args a = {.plants = 1000000, .w = 160, .h = 90, .spp = 4, .variants = 8,
                    .threads = (unsigned)sysconf(_SC_NPROCESSORS_ONLN), .forest = &bench_forest_main};
    if (parse(argc, argv, &a)) {
        fprintf(stderr, "usage: bench_scale [--plants N] [--threads N] [--size WxH] [--spp N] [--variants V] "
                        "[--forest main|weber_penn] [--compare]\n");
        return 1;
    }
    if (a.threads < 1) a.threads = 1;
    if (a.plants < 1) a.plants = 1;
    if (a.variants < 1) a.variants = 1;
    char cpu[256];
    bench_cpu_model(cpu, sizeof cpu);
    printf("machine: %s, %ld processors online\n", cpu, sysconf(_SC_NPROCESSORS_ONLN));
    return a.compare ? run_compare(&a) : run_one(&a);
}
