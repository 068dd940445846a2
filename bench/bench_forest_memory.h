/* bench_forest_memory.h — what a forest of N plants costs in resident memory, stage by stage
 * through the render pipeline: a forest of bench_forest.h (a plan's species, with their age
 * variants, on a terrain sized to keep the density of 1 M plants on 2 km x 2 km), its plants
 * placed, Embree's instances, the crown proxies, the top BVH, then the real render
 * (render_setup_new, render_setup_run) seen from beyond one corner. Each stage's resident memory
 * over the species alone, and the process's peak after the species were built (the kernel's
 * high-water mark reset then, so the plugins' own peak while they grow the models does not
 * count). bench_forest_measure_apart does the same in a child process, so that forests measured
 * one after another in one run do not share a heap: a forest freed leaves pages the next one
 * would reuse without the kernel counting them.
 *
 * What an instance costs, apart from its prototype: bench_forest_bytes_per_instance, the growth
 * of the peak between two plant counts over the plants added (the species, their BVHs, the
 * lights and the film are the same at both counts and drop out).
 *
 * Header-only, for the benchmark executables and the tests that measure with them (Linux: it
 * reads /proc/self and forks). Needs SYLVA_SOURCE_DIR (bench_forest.h). */
#ifndef SYLVA_BENCH_FOREST_MEMORY_H
#define SYLVA_BENCH_FOREST_MEMORY_H

#include <malloc.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bench_forest.h"
#include "render/accel.h"
#include "render/camera.h"
#include "render/crown_proxy.h"
#include "render/render.h"
#include "util/phase_times.h"
#include "util/progress.h"

#define BENCH_MALLOC_THRESHOLD (128 * 1024) /* bytes: glibc's default, held fixed in a measuring child */

/* One forest's figures. Memory in MiB, times in seconds. */
typedef struct bench_forest_figures {
    uint32_t plants, species, prototypes, proxies;
    uint64_t triangles;    /* of every prototype */
    double side;           /* the terrain's side, metres */
    double species_s;      /* the tree plugins growing the variants */
    double species_mib;    /* resident with the species and terrain alone */
    /* resident over the species alone after each stage */
    double plants_mib, instances_mib, embree_mib, proxies_mib, bvh_mib, setup_mib, render_mib;
    double peak_mib;       /* the process's peak resident memory after the species were built */
    int peak_reset;        /* 1 when the kernel's high-water mark was reset after the species */
    double embree_s, proxies_s, bvh_s, setup_s, pixels_s, render_s;
} bench_forest_figures;

/* The peak resident memory the kernel has seen since it was last reset (VmHWM), MiB; the
 * process's whole peak (getrusage) where /proc/self/status is missing. */
static inline double bench_hwm_mib(void)
{
    FILE *f = fopen("/proc/self/status", "r");
    char line[256];
    double kib = -1;
    while (f && fgets(line, sizeof line, f))
        if (!strncmp(line, "VmHWM:", 6)) kib = atof(line + 6);
    if (f) fclose(f);
    return kib >= 0 ? kib / 1024.0 : bench_peak_mib();
}

/* Resets the kernel's high-water mark to the resident memory now. Returns 1 when it could. */
static inline int bench_hwm_reset(void)
{
    FILE *f = fopen("/proc/self/clear_refs", "w");
    if (!f) return 0;
    int ok = fputs("5", f) >= 0;
    return fclose(f) == 0 && ok;
}

/* The view from beyond the terrain's south-west corner over the forest. */
static inline void bench_corner_view(scene *s, double side)
{
    double z0 = 0;
    scene_terrain_height(s, side / 2, side / 2, &z0);
    s->camera.position[0] = -0.02 * side, s->camera.position[1] = -0.02 * side;
    s->camera.position[2] = bench_hill_height(0, 0, side) + 30;
    s->camera.has_look_at = 1;
    s->camera.look_at[0] = side / 2, s->camera.look_at[1] = side / 2, s->camera.look_at[2] = z0;
}

static inline double bench_per_plant(double mib, uint32_t n)
{
    return mib * 1024.0 * 1024.0 / n;
}

static inline void bench_stage(FILE *log, const char *what, double mib, uint32_t n, const char *more)
{
    if (log) fprintf(log, "  %-44s %9.0f %10.1f%s\n", what, mib, bench_per_plant(mib, n), more);
}

/* The plants, their instances, Embree's scene built as the renderer builds it, stage by stage,
 * into f (memory over `base` MiB). Returns 0, or -1 with err set. */
static inline int bench_forest_stages(scene *s, uint32_t n, unsigned threads, uint32_t w, uint32_t h, double base,
                                      bench_forest_figures *f, FILE *log, err_buf *err)
{
    char more[160];
    sylva_plant *plants = bench_forest_plants(s, n, f->side);
    if (!plants) return err_nomem(err, "out of memory for %u plants", n);
    bench_stage(log, "plants from the ecology (sylva_plant)", f->plants_mib = bench_rss_mib() - base, n, "");
    int rc = scene_place_plants(s, plants, n, err);
    free(plants);
    if (rc) return -1;
    snprintf(more, sizeof more, "  (sizeof(instance) %zu)", sizeof(instance));
    bench_stage(log, "scene instance records", f->instances_mib = bench_rss_mib() - base, n, more);
    double t0 = progress_now();
    accel acc;
    if (accel_build_open(&acc, s, threads, NULL, err)) return -1;
    f->embree_mib = bench_rss_mib() - base, f->embree_s = progress_now() - t0;
    snprintf(more, sizeof more, "  (%.2f s)", f->embree_s);
    bench_stage(log, "+ Embree instances (and prototypes' BVHs)", f->embree_mib, n, more);
    camera cam;
    camera_init(&cam, &s->camera, w, h);
    t0 = progress_now();
    if (crown_proxies_attach(&acc, &cam, v3(0.0f, 0.7071f, 0.7071f), s->image.crown_proxy, threads, err)) {
        accel_free(&acc);
        return -1;
    }
    f->proxies = acc.proxies ? acc.proxies->n : 0;
    f->proxies_mib = bench_rss_mib() - base, f->proxies_s = progress_now() - t0;
    snprintf(more, sizeof more, "  (%u proxies, %.2f s)", f->proxies, f->proxies_s);
    bench_stage(log, "+ crown proxies (envelopes, user geometry)", f->proxies_mib, n, more);
    t0 = progress_now();
    rc = accel_commit(&acc, err);
    f->bvh_mib = bench_rss_mib() - base, f->bvh_s = progress_now() - t0;
    snprintf(more, sizeof more, "  (peak so far %.1f B/plant, %.2f s)", bench_per_plant(bench_hwm_mib() - base, n),
             f->bvh_s);
    if (!rc) bench_stage(log, "+ top BVH (instances and proxies)", f->bvh_mib, n, more);
    accel_free(&acc);
    return rc;
}

/* The real render of s at w x h, spp samples, into f. Returns 0, or -1 with err set. */
static inline int bench_forest_render(scene *s, uint32_t n, unsigned threads, uint32_t w, uint32_t h, uint32_t spp,
                                      double base, bench_forest_figures *f, FILE *log, err_buf *err)
{
    render_options ro = {.threads = threads, .quiet = 1, .width = w, .height = h, .spp = spp};
    render_stats st = {0};
    double t0 = progress_now();
    render_setup *rs = render_setup_new(s, &ro, err);
    if (!rs) return -1;
    f->setup_mib = bench_rss_mib() - base;
    film *pixels = render_setup_run(rs, &ro, &st, err);
    f->render_s = progress_now() - t0, f->render_mib = bench_rss_mib() - base;
    f->setup_s = st.build_seconds, f->pixels_s = st.render_seconds;
    bench_stage(log, "render setup (BVH, lights, proxies calibrated)", f->setup_mib, n, "");
    char more[160];
    snprintf(more, sizeof more, "  (setup %.2f s, pixels %.2f s)", f->setup_s, f->pixels_s);
    if (pixels) bench_stage(log, "+ pixels and film", f->render_mib, n, more);
    film_free(pixels);
    render_setup_free(rs);
    return pixels ? 0 : -1;
}

/* A forest of n plants of plan's species, `variants` age variants each, measured into *f and
 * told stage by stage on log (NULL: silent). Returns 0, or -1 with err set. */
static inline int bench_forest_measure(const bench_forest_plan *plan, uint32_t n, uint32_t variants, unsigned threads,
                                       uint32_t w, uint32_t h, uint32_t spp, FILE *log, bench_forest_figures *f,
                                       err_buf *err)
{
    memset(f, 0, sizeof *f);
    f->plants = n = n ? n : 1;
    f->side = 2000 * sqrt(n / 1e6);
    phase_times times = {{0}};
    scene *s = bench_forest_species_of(plan, variants, f->side, threads, &times, err);
    if (!s) return -1;
    f->species_s = times.seconds[PHASE_TREES];
    f->species = s->n_species, f->prototypes = s->n_prototypes;
    for (uint32_t p = 0; p < s->n_prototypes; p++) f->triangles += s->prototypes[p].mesh->nt;
    bench_corner_view(s, f->side);
    malloc_trim(0); /* the plugins' freed transients back to the kernel, not reused unseen */
    f->peak_reset = bench_hwm_reset();
    double base = f->species_mib = bench_rss_mib();
    if (log) {
        fprintf(log, "%u plants of %s, %u species x %u variants (%u prototypes, %llu triangles) on %.0f m x %.0f m, "
                     "%u threads, %ux%u at %u spp\n", n, plan->name, f->species, variants, f->prototypes,
                (unsigned long long)f->triangles, f->side, f->side, threads, w, h, spp);
        fprintf(log, "  species and terrain alone: %.0f MiB resident (grown in %.2f s)\n", base, f->species_s);
        fprintf(log, "  %-44s %9s %10s\n", "stage (resident over the species alone)", "MiB", "B/plant");
    }
    int rc = bench_forest_stages(s, n, threads, w, h, base, f, log, err);
    if (!rc) rc = bench_forest_render(s, n, threads, w, h, spp, base, f, log, err);
    f->peak_mib = f->peak_reset ? bench_hwm_mib() : bench_peak_mib();
    if (!rc && log)
        fprintf(log, "  peak resident %.0f MiB%s: %.0f B per plant over the species alone; whole render %.2f s\n",
                f->peak_mib, f->peak_reset ? " after the species" : " (the whole run's: no high-water reset)",
                bench_per_plant(f->peak_mib - base, n), f->render_s);
    scene_free(s);
    return rc;
}

/* bench_forest_measure in a child process of its own (its lines on log as it goes). Returns 0,
 * or -1 with err set (the child's sentence, or why it could not run). */
static inline int bench_forest_measure_apart(const bench_forest_plan *plan, uint32_t n, uint32_t variants,
                                             unsigned threads, uint32_t w, uint32_t h, uint32_t spp, FILE *log,
                                             bench_forest_figures *f, err_buf *err)
{
    struct {
        bench_forest_figures f;
        int rc;
        char msg[ERR_MSG_MAX];
    } answer;
    memset(&answer, 0, sizeof answer);
    memset(f, 0, sizeof *f);
    int fd[2];
    fflush(NULL);
    if (pipe(fd)) return err_fail(err, ERR_INTERNAL, "bench: no pipe for the forest's child process");
    pid_t pid = fork();
    if (pid < 0) return close(fd[0]), close(fd[1]), err_fail(err, ERR_INTERNAL, "bench: no child process");
    if (pid == 0) {
        close(fd[0]);
        /* Blocks of 128 KiB and more mapped on their own and every freed one handed back, the
         * heap's top trimmed: what the run frees is not reused unseen by what it allocates later
         * (glibc otherwise raises its mapping threshold as large blocks are freed). */
        mallopt(M_MMAP_THRESHOLD, BENCH_MALLOC_THRESHOLD);
        mallopt(M_TRIM_THRESHOLD, BENCH_MALLOC_THRESHOLD);
        err_buf e = {{0}};
        answer.rc = bench_forest_measure(plan, n, variants, threads, w, h, spp, log, &answer.f, &e);
        snprintf(answer.msg, sizeof answer.msg, "%s", e.msg);
        fflush(NULL);
        ssize_t put = write(fd[1], &answer, sizeof answer);
        _exit(put == (ssize_t)sizeof answer && !answer.rc ? 0 : 1);
    }
    close(fd[1]);
    size_t got = 0;
    while (got < sizeof answer) {
        ssize_t r = read(fd[0], (char *)&answer + got, sizeof answer - got);
        if (r <= 0) break;
        got += (size_t)r;
    }
    close(fd[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (got != sizeof answer) return err_fail(err, ERR_INTERNAL, "bench: the forest's child process ended early");
    *f = answer.f;
    return answer.rc ? err_fail(err, ERR_INTERNAL, "%s", answer.msg) : 0;
}

/* Bytes of peak resident memory each plant adds between forests of a->plants and b->plants of
 * the same species (b the larger). */
static inline double bench_forest_bytes_per_instance(const bench_forest_figures *a, const bench_forest_figures *b)
{
    return (b->peak_mib - b->species_mib - (a->peak_mib - a->species_mib)) * 1024.0 * 1024.0 /
           ((double)b->plants - a->plants);
}

#endif
