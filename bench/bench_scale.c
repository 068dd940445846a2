/* bench_scale.c — memory of a large forest through the whole render pipeline, per instance.
 *
 * N plants of the main job's 4 species x 8 age variants (the real models from their tree
 * plugins, bench_forest.h) on a terrain sized to keep the density of bench_ecology's 1 M plants
 * on 2 km x 2 km, seen from beyond one corner so that most of them are distant crown proxies.
 * Each stage's resident memory over the species alone, divided by N: the plants as the ecology
 * hands them over, the scene's instance records, Embree's instances, the crown proxies, the
 * top BVH over both (built once, as the renderer does); then the real render (render_setup_new and render_setup_run at a small size: BVH,
 * lights, proxies and their calibration, pixels, film) and the process's peak memory against
 * the goal that 10 M plants render within 8 GB. One N per run, so the peak is that N's.
 *
 * Usage: bench_scale [--plants N] [--threads N] [--size WxH] [--spp N]
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench_forest.h"
#include "bench_machine.h"
#include "render/accel.h"
#include "render/camera.h"
#include "render/crown_proxy.h"
#include "render/render.h"
#include "scene_build/scene_build.h"
#include "util/phase_times.h"
#include "util/progress.h"

#define GOAL_PLANTS 10e6
#define GOAL_MIB (8.0 * 1024)

static double per_plant(double mib, uint32_t n)
{
    return mib * 1024.0 * 1024.0 / n;
}

/* The view from beyond the terrain's south-west corner over the forest. */
static void corner_view(scene *s, double side)
{
    double z0 = 0;
    scene_terrain_height(s, side / 2, side / 2, &z0);
    s->camera.position[0] = -0.02 * side, s->camera.position[1] = -0.02 * side;
    s->camera.position[2] = bench_hill_height(0, 0, side) + 30;
    s->camera.has_look_at = 1;
    s->camera.look_at[0] = side / 2, s->camera.look_at[1] = side / 2, s->camera.look_at[2] = z0;
}

static int run(uint32_t n, unsigned threads, uint32_t w, uint32_t h, uint32_t spp)
{
    err_buf err = {{0}};
    double side = 2000 * sqrt(n / 1e6);
    phase_times times = {{0}};
    scene *s = bench_forest_species(8, side, threads, &times, &err);
    if (!s) return fprintf(stderr, "bench: %s\n", err.msg), 4;
    corner_view(s, side);
    double base = bench_rss_mib();
    printf("%u plants of %u species x 8 variants on %.0f m x %.0f m, %u threads, %ux%u at %u spp\n", n,
           s->n_species, side, side, threads, w, h, spp);
    printf("  species and terrain alone: %.0f MiB resident\n", base);
    printf("  %-44s %9s %10s\n", "stage (resident over the species alone)", "MiB", "B/plant");

    sylva_plant *plants = bench_forest_plants(s, n, side);
    if (!plants) return fprintf(stderr, "bench: out of memory\n"), 4;
    double m_plants = bench_rss_mib() - base;
    printf("  %-44s %9.0f %10.1f\n", "plants from the ecology (sylva_plant)", m_plants, per_plant(m_plants, n));
    if (scene_place_plants(s, plants, n, &err)) return fprintf(stderr, "bench: %s\n", err.msg), 4;
    free(plants);
    double m_inst = bench_rss_mib() - base;
    printf("  %-44s %9.0f %10.1f  (sizeof(instance) %zu)\n", "scene instance records", m_inst,
           per_plant(m_inst, n), sizeof(instance));

    double t0 = progress_now();
    accel acc;
    if (accel_build_open(&acc, s, threads, &err)) return fprintf(stderr, "bench: %s\n", err.msg), 4;
    double m_open = bench_rss_mib() - base;
    printf("  %-44s %9.0f %10.1f  (%.2f s)\n", "+ Embree instances (and prototypes' BVHs)", m_open, per_plant(m_open, n),
           progress_now() - t0);
    camera cam;
    camera_init(&cam, &s->camera, w, h);
    t0 = progress_now();
    if (crown_proxies_attach(&acc, &cam, v3(0.0f, 0.7071f, 0.7071f), s->image.crown_proxy, threads, &err))
        return fprintf(stderr, "bench: %s\n", err.msg), 4;
    double m_proxy = bench_rss_mib() - base;
    printf("  %-44s %9.0f %10.1f  (%u proxies, %.2f s)\n", "+ crown proxies (envelopes, user geometry)", m_proxy,
           per_plant(m_proxy, n), acc.proxies ? acc.proxies->n : 0, progress_now() - t0);
    t0 = progress_now();
    if (accel_commit(&acc, &err)) return fprintf(stderr, "bench: %s\n", err.msg), 4;
    double m_bvh = bench_rss_mib() - base, peak_bvh = bench_peak_mib() - base;
    printf("  %-44s %9.0f %10.1f  (peak so far %.1f B/plant, %.2f s)\n", "+ top BVH (instances and proxies)", m_bvh,
           per_plant(m_bvh, n), per_plant(peak_bvh, n), progress_now() - t0);
    accel_free(&acc);

    render_options ro = {.threads = threads, .quiet = 1, .width = w, .height = h, .spp = spp};
    render_stats st = {0};
    t0 = progress_now();
    render_setup *rs = render_setup_new(s, &ro, &err);
    if (!rs) return fprintf(stderr, "bench: %s\n", err.msg), 4;
    double m_setup = bench_rss_mib() - base;
    film *f = render_setup_run(rs, &ro, &st, &err);
    if (!f) return fprintf(stderr, "bench: %s\n", err.msg), 4;
    double t_all = progress_now() - t0, m_render = bench_rss_mib() - base;
    printf("  %-44s %9.0f %10.1f\n", "render setup (BVH, lights, proxies calibrated)", m_setup, per_plant(m_setup, n));
    printf("  %-44s %9.0f %10.1f  (setup %.2f s, pixels %.2f s)\n", "+ pixels and film", m_render,
           per_plant(m_render, n), st.build_seconds, st.render_seconds);
    double peak = bench_peak_mib();
    double per = per_plant(peak - base, n);
    printf("  peak resident %.0f MiB: %.0f B per plant over the species alone; 10 M plants at this rate: "
           "%.0f MiB (goal <= %.0f MiB)\n", peak, per, base + per * GOAL_PLANTS / (1024.0 * 1024.0), GOAL_MIB);
    printf("  whole render %.2f s\n", t_all);
    film_free(f);
    render_setup_free(rs);
    scene_free(s);
    return 0;
}

int main(int argc, char **argv)
{
    uint32_t plants = 1000000, w = 160, h = 90, spp = 4;
    unsigned threads = (unsigned)sysconf(_SC_NPROCESSORS_ONLN);
    for (int i = 1; i < argc; i++) {
        if (i + 1 < argc && !strcmp(argv[i], "--plants")) plants = (uint32_t)atol(argv[++i]);
        else if (i + 1 < argc && !strcmp(argv[i], "--threads")) threads = (unsigned)atol(argv[++i]);
        else if (i + 1 < argc && !strcmp(argv[i], "--spp")) spp = (uint32_t)atol(argv[++i]);
        else if (i + 1 < argc && !strcmp(argv[i], "--size") && sscanf(argv[i + 1], "%ux%u", &w, &h) == 2) i++;
        else {
            fprintf(stderr, "usage: bench_scale [--plants N] [--threads N] [--size WxH] [--spp N]\n");
            return 1;
        }
    }
    if (threads < 1) threads = 1;
    if (plants < 1) plants = 1;
    char cpu[256];
    bench_cpu_model(cpu, sizeof cpu);
    printf("machine: %s, %ld processors online\n", cpu, sysconf(_SC_NPROCESSORS_ONLN));
    return run(plants, threads, w, h, spp);
}
