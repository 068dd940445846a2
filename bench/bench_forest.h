/* bench_forest.h — the forest the instancing benchmarks place: the main job's four species
 * (scenes/default.yaml, which includes scenes/species/forest.yaml: beech and spruce by the vessel
 * model, maple by Aono-Kunii, the shrub by the L-system) built by their plugins, on a hilly
 * 513 x 513 terrain, and plants of them spread at random over it; the process's memory as the
 * kernel counts it. Header-only, for the benchmark executables. */
#ifndef SYLVA_BENCH_FOREST_H
#define SYLVA_BENCH_FOREST_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <unistd.h>

#include "plugin/plugin_host.h"
#include "scene/heightfield.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "util/rng.h"

/* The process's peak resident memory so far, MiB. */
static inline double bench_peak_mib(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_maxrss / 1024.0;
}

/* The process's resident memory now, MiB (0 where /proc is missing). */
static inline double bench_rss_mib(void)
{
    long pages = 0, resident = 0;
    FILE *f = fopen("/proc/self/statm", "r");
    if (!f) return 0;
    if (fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
    fclose(f);
    return resident * (double)sysconf(_SC_PAGESIZE) / (1024.0 * 1024.0);
}

static inline float bench_hill_height(double x, double y, double side)
{
    double u = x / side, v = y / side;
    return (float)(40 * sin(5 * u) * cos(4 * v) + 25 * sin(11 * u + 3 * v) + 60 * u);
}

/* A terrain of n x n nodes over [0, side] x [0, side] metres; NULL when out of memory. The caller
 * frees it (heightfield_free). */
static inline sylva_heightfield *bench_terrain_new(uint32_t n, double side)
{
    sylva_heightfield *hf = calloc(1, sizeof *hf);
    float *z = malloc((size_t)n * n * sizeof *z);
    if (!hf || !z) return free(hf), free(z), NULL;
    *hf = (sylva_heightfield){.size = sizeof *hf, .nx = n, .ny = n, .dx = side / (n - 1), .dy = side / (n - 1),
                              .z = z, .water_material = -1};
    for (uint32_t j = 0; j < n; j++)
        for (uint32_t i = 0; i < n; i++) z[(size_t)j * n + i] = bench_hill_height(i * hf->dx, j * hf->dy, side);
    return hf;
}

/* The main job's scene with `variants` age variants of each species and no plants, on a
 * 513 x 513 terrain of side x side metres instead of its own; NULL with err set. The caller
 * frees it (scene_free). */
static inline scene *bench_forest_species(uint32_t variants, double side, unsigned threads, phase_times *times,
                                          err_buf *err)
{
    plugin_registry *reg = plugin_registry_open(err);
    scene_file *sf = reg ? scene_file_load(SYLVA_SOURCE_DIR "/scenes/default.yaml", reg, err) : NULL;
    scene *s = NULL;
    if (sf) {
        for (uint32_t i = 0; i < sf->n_species; i++) sf->species[i].variants = variants;
        build_options bo = {.quiet = 1, .no_ecology = 1, .threads = threads, .times = times};
        s = scene_build(sf, reg, &bo, err);
    }
    if (s) {
        heightfield_free(s->terrain);
        if (!(s->terrain = bench_terrain_new(513, side))) {
            err_nomem(err, "out of memory for the terrain");
            scene_free(s);
            s = NULL;
        }
    }
    scene_file_free(sf);
    plugin_registry_free(reg);
    return s;
}

/* n plants of s's species in turn, at random over [0, side]^2 on the terrain, 1 to 21 m high, of
 * every age; NULL when out of memory. The caller frees the array. */
static inline sylva_plant *bench_forest_plants(const scene *s, uint32_t n, double side)
{
    sylva_plant *plants = malloc((size_t)(n ? n : 1) * sizeof *plants);
    if (!plants) return NULL;
    sylva_rng r;
    rng_stream(&r, 7, "bench plants", 0);
    for (uint32_t i = 0; i < n; i++)
        plants[i] = (sylva_plant){.size = sizeof(sylva_plant), .species = i % s->n_species,
                                  .position = {side * rng_next_double(&r), side * rng_next_double(&r), 0},
                                  .snap_to_terrain = 1, .rotation = 2 * M_PI * rng_next_double(&r),
                                  .height = 1 + 20 * rng_next_double(&r), .age = 0.01 + 0.99 * rng_next_double(&r)};
    return plants;
}

#endif
