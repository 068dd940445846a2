/* bench_ecology.c — the ecology plugin's two costs.
 *
 * 1. Instancing: the render scene for 1,000,000 plants of the main job's 4 species x 8 age
 *    variants, the real models from their tree plugins, built by the host's scene_place_plants
 *    (variant by age, scale by height, turn, standing on a 513 x 513 terrain), then Embree's
 *    BVH over it; each time, their total (what re-rendering a saved forest costs before the
 *    pixels; goal 3 s) and peak memory (goal 1.5 GB).
 * 2. Simulation: the four default species (beech, maple, spruce, shrubs) for 300 years on a
 *    hilly terrain sized to hold about 100,000 living plants, through the plugin's model;
 *    per-year time against the plant count (goal: 20 s in all on 2 cores, linear in the plants).
 *
 * Usage: bench_ecology [--plants N] [--side METRES] [--years N] [--threads N] [--skip-instances]
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "bench_forest.h"
#include "eco_sim.h"
#include "render/accel.h"
#include "plugin/plugin_host.h"
#include "scene/heightfield.h"
#include "scene_build/host.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "util/phase_times.h"
#include "util/progress.h"
#include "util/rng.h"

static int bench_instances(uint32_t n_plants, unsigned threads)
{
    err_buf err = {{0}};
    double side = 2000;
    phase_times times = {{0}};
    scene *s = bench_forest_species(8, side, threads, &times, &err);
    if (!s) return fprintf(stderr, "bench: %s\n", err.msg), 4;
    uint64_t tris = 0;
    for (uint32_t p = 0; p < s->n_prototypes; p++) tris += s->prototypes[p].mesh->nt;
    sylva_plant *plants = bench_forest_plants(s, n_plants, side);
    if (!plants) return fprintf(stderr, "bench: out of memory\n"), 4;
    double before = bench_peak_mib();
    double t0 = progress_now();
    if (scene_place_plants(s, plants, n_plants, &err)) return fprintf(stderr, "bench: %s\n", err.msg), 4;
    double t_place = progress_now() - t0;
    free(plants);
    printf("instancing: %u plants of the main job's %u species x 8 variants (%llu prototype triangles in all, "
           "from their tree plugins) on a 513 x 513 terrain, %u threads\n", s->n_instances, s->n_species,
           (unsigned long long)tris, threads);
    printf("  tree variants (the plugins): %.3f s\n", times.seconds[PHASE_TREES]);
    printf("  plants -> instances (scene_place_plants): %.3f s; peak memory %.0f MiB (%.0f MiB before)\n", t_place,
           bench_peak_mib(), before);
    accel acc;
    t0 = progress_now();
    if (accel_build(&acc, s, threads, &err)) return fprintf(stderr, "bench: %s\n", err.msg), 4;
    double t_bvh = progress_now() - t0;
    printf("  Embree scene over them (accel_build: prototypes and instances): %.3f s; peak memory %.0f MiB\n", t_bvh,
           bench_peak_mib());
    double total = times.seconds[PHASE_TREES] + t_place + t_bvh;
    printf("  scene build of a saved 1 M-plant forest (variants + instances + BVH): %.2f s (goal <= 3 s); "
           "peak %.0f MiB (goal <= 1536 MiB)\n", total, bench_peak_mib());
    accel_free(&acc);
    scene_free(s);
    return 0;
}

/* The model's random source: the host's streams, as the plugin file makes it. */
static void host_stream(void *ctx, sylva_rng *rng, const char *purpose, uint64_t index)
{
    host_api_table()->rng_init(ctx, rng, purpose, index);
}

static int bench_simulation(double side, uint32_t years, unsigned threads)
{
    scene *sc = scene_new();
    err_buf err = {{0}};
    sylva_host host;
    host_init(&host, sc, "/tmp", 1, "ecology benchmark", &err);
    host.kind = SYLVA_KIND_ECOLOGY, host.quiet = 1, host.n_species = 4;
    const sylva_host_api *api = host_api_table();
    uint32_t n = (uint32_t)(side / 4) + 1;
    sylva_heightfield *hf = bench_terrain_new(n, side);
    const char *names[4] = {"beech", "maple", "spruce", "shrub"};
    sylva_species_info info[4];
    for (int i = 0; i < 4; i++)
        info[i] = (sylva_species_info){.size = sizeof info[i], .name = names[i], .model_height = 20};
    sylva_ecology_request req = {.size = sizeof req, .terrain = hf, .species = info, .n_species = 4};
    eco_config cfg = {.factors = {.patches = (uint32_t)(side / 8), .rain = 1, .water_humidity = 10, .runoff = 1,
                                  .humidity_blur = 10, .wind_azimuth_deg = 270, .wind_samples = 10, .shelter_deg = 45,
                                  .latitude_deg = 46, .sun_samples = 9, .ambient = 0.2, .threads = threads},
                      .area = {-1, 0, 0, 0}, .max_plants = 5000000, .threads = threads};
    eco_sim *s = NULL;
    eco_random rnd = {.stream = host_stream, .uniform = api->rng_uniform, .ctx = &host};
    plugin_err fail = {0};
    double t0 = progress_now();
    if (eco_sim_new(&rnd, NULL, &cfg, NULL, &req, &s, &fail)) return fprintf(stderr, "bench: %s\n", fail.msg), 4;
    double t_factors = progress_now() - t0;
    printf("simulation: 4 species on %.0f x %.0f m, %u x %u patches of %.1f m, %u threads (factors in %.2f s)\n",
           side, side, s->terrain.ni, s->terrain.nk, s->terrain.kx, threads, t_factors);
    printf("  year   plants   ms/year   us/plant\n");
    double total = 0, sum_xy = 0, sum_xx = 0;
    uint64_t plant_years = 0;
    uint32_t most = 0;
    for (uint32_t y = 1; y <= years; y++) {
        double a = progress_now();
        if (eco_sim_step(s, &rnd, &fail)) return fprintf(stderr, "bench: %s\n", fail.msg), 4;
        double dt = progress_now() - a;
        uint32_t count = eco_sim_count(s);
        total += dt, plant_years += count, most = count > most ? count : most;
        sum_xy += (double)count * dt, sum_xx += (double)count * count;
        if (y % 20 == 0 || y == years)
            printf("  %4u %8u %9.2f %10.3f\n", y, count, 1e3 * dt, count ? 1e6 * dt / count : 0.0);
    }
    double slope = sum_xy / sum_xx; /* least squares through the origin */
    printf("  %u years in %.2f s (goal <= 20 s); most plants %u; %.2f us per plant-year on average\n", years, total,
           most, 1e6 * total / (double)plant_years);
    printf("  per-year time ~ %.3f us x plants (least squares through the origin)\n", 1e6 * slope);
    eco_sim_free(s);
    host_release(&host);
    heightfield_free(hf);
    scene_free(sc);
    return 0;
}

int main(int argc, char **argv)
{
    uint32_t plants = 1000000, years = 300;
    double side = 560; /* about 100,000 living plants */
    unsigned threads = (unsigned)sysconf(_SC_NPROCESSORS_ONLN);
    int skip_instances = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--skip-instances")) skip_instances = 1;
        else if (i + 1 < argc && !strcmp(argv[i], "--plants")) plants = (uint32_t)atol(argv[++i]);
        else if (i + 1 < argc && !strcmp(argv[i], "--side")) side = atof(argv[++i]);
        else if (i + 1 < argc && !strcmp(argv[i], "--years")) years = (uint32_t)atol(argv[++i]);
        else if (i + 1 < argc && !strcmp(argv[i], "--threads")) threads = (unsigned)atol(argv[++i]);
        else {
            fprintf(stderr, "usage: bench_ecology [--plants N] [--side METRES] [--years N] [--threads N] "
                    "[--skip-instances]\n");
            return 1;
        }
    }
    if (threads < 1) threads = 1;
    printf("machine: %ld processors online\n", sysconf(_SC_NPROCESSORS_ONLN));
    int rc = skip_instances ? 0 : bench_instances(plants, threads);
    if (!rc) rc = bench_simulation(side, years, threads);
    return rc;
}
