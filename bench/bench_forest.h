/* bench_forest.h — the forests the instancing benchmarks place: the main job's four species
 * (scenes/default.yaml, which includes scenes/species/forest.yaml: beech and spruce by the vessel
 * model, maple by Aono-Kunii, the shrub by the L-system), or four Weber-Penn species of the
 * species library (bench/forest_weber_penn.yaml: California black oak, quaking aspen, tamarack,
 * European larch), built by their plugins, on a hilly 513 x 513 terrain, and plants of them
 * spread at random over it; the process's memory as the kernel counts it. Header-only, for the
 * benchmark executables and the tests that measure with them. */
#ifndef SYLVA_BENCH_FOREST_H
#define SYLVA_BENCH_FOREST_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
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

/* Which species a forest is made of: the species of the scene file `scene` (its terrain, sky and
 * materials come along), only those `keep` names when it is not NULL. */
typedef struct bench_forest_plan {
    const char *name;             /* for the benchmark's lines */
    const char *scene;            /* path */
    const char *const *keep;      /* NULL-terminated species names, or NULL for every species */
} bench_forest_plan;

static const char *const bench_weber_penn_species[] = {"ca_black_oak", "quaking_aspen", "tamarack",
                                                       "european_larch", NULL};
static const bench_forest_plan bench_forest_main = {"the main job's species (vessel, Aono-Kunii, L-system)",
                                                    SYLVA_SOURCE_DIR "/scenes/default.yaml", NULL};
static const bench_forest_plan bench_forest_weber_penn = {"Weber-Penn library species",
                                                          SYLVA_SOURCE_DIR "/bench/forest_weber_penn.yaml",
                                                          bench_weber_penn_species};

/* Keeps the species plan->keep names at the front of sf->species, in that order, and only
 * those. Returns 0, or -1 with err set when one is missing. */
static inline int bench_forest_keep(scene_file *sf, const bench_forest_plan *plan, err_buf *err)
{
    if (!plan->keep) return 0;
    uint32_t kept = 0;
    for (const char *const *name = plan->keep; *name; name++) {
        uint32_t i = kept;
        while (i < sf->n_species && strcmp(sf->species[i].name, *name)) i++;
        if (i == sf->n_species) return err_fail(err, ERR_INPUT, "%s has no species %s", plan->scene, *name);
        species_spec t = sf->species[kept];
        sf->species[kept++] = sf->species[i];
        sf->species[i] = t;
    }
    sf->n_species = kept; /* the entries past it stay in the file's arena */
    return 0;
}

/* The plan's scene with `variants` age variants of each of its species and no plants, on a
 * 513 x 513 terrain of side x side metres instead of its own; NULL with err set. The caller
 * frees it (scene_free). */
static inline scene *bench_forest_species_of(const bench_forest_plan *plan, uint32_t variants, double side,
                                             unsigned threads, phase_times *times, err_buf *err)
{
    plugin_registry *reg = plugin_registry_open(err);
    scene_file *sf = reg ? scene_file_load(plan->scene, reg, err) : NULL;
    scene *s = NULL;
    if (sf && !bench_forest_keep(sf, plan, err)) {
        for (uint32_t i = 0; i < sf->n_species; i++) sf->species[i].variants = variants;
        build_options bo = {.quiet = 1, .no_ecology = 1, .threads = threads, .times = times};
        s = scene_build(sf, reg, &bo, err);
    }
    if (s) {
        int surveyed = s->surveyed == s->terrain; /* one heightfield for both (a terrain without a plugin) */
        heightfield_free(s->terrain);
        s->terrain = bench_terrain_new(513, side);
        if (surveyed) s->surveyed = s->terrain;
        if (!s->terrain) {
            err_nomem(err, "out of memory for the terrain");
            scene_free(s);
            s = NULL;
        }
    }
    scene_file_free(sf);
    plugin_registry_free(reg);
    return s;
}

/* The main job's scene with `variants` age variants of each species and no plants
 * (bench_forest_species_of the main plan). */
static inline scene *bench_forest_species(uint32_t variants, double side, unsigned threads, phase_times *times,
                                          err_buf *err)
{
    return bench_forest_species_of(&bench_forest_main, variants, side, threads, times, err);
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
