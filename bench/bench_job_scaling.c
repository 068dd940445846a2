/* bench_job_scaling.c — the whole main job, scene file to output files, on 1 and on N threads:
 * each phase's wall time (the `phases:` line of `sylva render`), the job's, and the ratios, so
 * the figure on a machine with more cores can be predicted phase by phase (Amdahl: a phase that
 * speeds up by r on N threads runs the fraction p = (1 - 1/r) / (1 - 1/N) of its work in
 * parallel). Runs alternate between the thread counts so that a change in the machine's load
 * falls on both; the best of the repetitions is kept. The process CPU time of each run is printed
 * beside its wall time: on a machine shared with other work, a 1-thread run whose CPU time is
 * well under its wall time was not given a whole core, and the ratio is then not the code's.
 * Usage:
 *   bench_job_scaling [SCENE] [--size WxH] [--spp N] [--threads N] [--reps N]
 * (default: scenes/default.yaml at 480x270, 16 spp, 1 against 2 threads, 2 repetitions). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "bench_machine.h"
#include "geometry/ground_cover_place.h"
#include "plugin/plugin_host.h"
#include "render/auto_exposure.h"
#include "render/render.h"
#include "scene/scene_build.h"
#include "scene/scene_file.h"
#include "util/phase_times.h"
#include "util/progress.h"

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

typedef struct job_run {
    phase_times phases;
    double wall, cpu;
    double setup_cpu, render_cpu; /* the process CPU time of the render setup (BVH, lights and
                                     proxies) and of the pixel loop: on 1 thread, their work
                                     whatever else the machine runs */
} job_run;

/* One whole job as `sylva render` runs it; 0 or -1 after printing the problem. */
static int run_job(const char *path, const plugin_registry *reg, uint32_t w, uint32_t h, uint32_t spp,
                   unsigned threads, const char *out_dir, job_run *run)
{
    memset(run, 0, sizeof *run);
    err_buf err = {{0}};
    double t0 = progress_now(), c0 = cpu_now();
    scene_file *sf = scene_file_load(path, reg, &err);
    build_options bo = {.quiet = 1, .threads = threads, .times = &run->phases};
    scene *s = sf ? scene_build(sf, reg, &bo, &err) : NULL;
    film *f = NULL;
    int rc = -1;
    if (!s) goto done;
    const double *ph = run->phases.seconds;
    phase_add(&run->phases, PHASE_SCENE_OTHER,
              progress_now() - t0 - ph[PHASE_TERRAIN] - ph[PHASE_TREES] - ph[PHASE_ECOLOGY]);
    double t = progress_now();
    if (ground_cover_add(s, &sf->ground_cover, w, h, NULL, &err)) goto done;
    phase_since(&run->phases, PHASE_GROUND_COVER, t);
    render_options ro = {.quiet = 1, .threads = threads, .spp = spp, .width = w, .height = h};
    render_stats st;
    double c = cpu_now();
    render_setup *rs = render_setup_new(s, &ro, &err);
    if (!rs) goto done;
    run->setup_cpu = cpu_now() - c, c = cpu_now();
    f = render_setup_run(rs, &ro, &st, &err);
    run->render_cpu = cpu_now() - c;
    render_setup_free(rs);
    if (!f) goto done;
    phase_add(&run->phases, PHASE_BVH, st.bvh_seconds);
    phase_add(&run->phases, PHASE_RENDER_SETUP, st.build_seconds - st.bvh_seconds);
    phase_add(&run->phases, PHASE_RENDER, st.render_seconds);
    t = progress_now();
    char exr[4200], png[4200];
    snprintf(exr, sizeof exr, "%s/job.exr", out_dir);
    snprintf(png, sizeof png, "%s/job.png", out_dir);
    double ev = s->image.exposure_set ? s->image.exposure : auto_exposure_stops(f);
    if (film_write_exr(f, &s->site, ev, exr, &err) || film_write_png(f, png, s->image.tone, ev, &err)) goto done;
    phase_since(&run->phases, PHASE_OUTPUT, t);
    run->wall = progress_now() - t0, run->cpu = cpu_now() - c0;
    rc = 0;
done:
    if (rc) fprintf(stderr, "bench_job_scaling: %s\n", err.msg);
    film_free(f);
    scene_free(s);
    scene_file_free(sf);
    return rc;
}

/* Keeps the run with the shortest wall time. */
static void keep_best(job_run *best, const job_run *r)
{
    if (!(best->wall > 0) || r->wall < best->wall) *best = *r;
}

/* The time of the job on n threads predicted from each phase's 1- and N-thread times. */
static double predict(const job_run *one, const job_run *many, unsigned n_threads, unsigned n)
{
    double total = 0;
    for (int p = 0; p < PHASE_COUNT; p++) {
        double t1 = one->phases.seconds[p], tn = many->phases.seconds[p];
        if (!(t1 > 0)) continue;
        double r = tn > 0 ? t1 / tn : 1, par = (1 - 1 / r) / (1 - 1.0 / n_threads);
        par = par < 0 ? 0 : par > 1 ? 1 : par;
        total += t1 * ((1 - par) + par / n);
    }
    return total;
}

int main(int argc, char **argv)
{
    const char *path = SYLVA_SOURCE_DIR "/scenes/default.yaml";
    uint32_t w = 480, h = 270, spp = 16, reps = 2;
    unsigned threads = 2;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--size") && v && sscanf(v, "%ux%u", &w, &h) == 2) i++;
        else if (!strcmp(a, "--spp") && v) spp = (uint32_t)atol(v), i++;
        else if (!strcmp(a, "--threads") && v) threads = (unsigned)atol(v), i++;
        else if (!strcmp(a, "--reps") && v) reps = (uint32_t)atol(v), i++;
        else if (a[0] != '-') path = a;
        else {
            fprintf(stderr, "usage: bench_job_scaling [SCENE] [--size WxH] [--spp N] [--threads N] [--reps N]\n");
            return 1;
        }
    }
    if (threads < 2 || !w || !h || !spp || !reps) {
        fprintf(stderr, "bench_job_scaling: --threads must be at least 2, sizes, spp and reps at least 1\n");
        return 1;
    }
    char cpu[256], out_dir[] = "/tmp/bench_job_scaling_XXXXXX";
    bench_cpu_model(cpu, sizeof cpu);
    if (!mkdtemp(out_dir)) {
        perror("bench_job_scaling: mkdtemp");
        return 3;
    }
    double load[3] = {0};
    if (getloadavg(load, 3) < 1) load[0] = -1;
    printf("machine: %s, %ld processors online, load average %.2f at the start\n", cpu,
           sysconf(_SC_NPROCESSORS_ONLN), load[0]);
    printf("job: %s at %ux%u, %u spp; 1 against %u threads, best of %u runs each, alternating\n", path, w, h, spp,
           threads, reps);
    err_buf err = {{0}};
    plugin_registry *reg = plugin_registry_open(&err);
    if (!reg) {
        fprintf(stderr, "bench_job_scaling: %s\n", err.msg);
        return 4;
    }
    job_run one = {0}, many = {0}, r;
    for (uint32_t k = 0; k < reps; k++) {
        for (int which = 0; which < 2; which++) {
            unsigned n = which ? threads : 1;
            if (run_job(path, reg, w, h, spp, n, out_dir, &r)) return 4;
            printf("  run %u, %2u thread%s: wall %6.2fs, CPU %6.2fs\n", k + 1, n, n == 1 ? " " : "s", r.wall, r.cpu);
            fflush(stdout);
            keep_best(which ? &many : &one, &r);
        }
    }
    printf("\n%-20s %10s %10s %8s\n", "phase", "1 thread", "threads", "ratio");
    for (int p = 0; p < PHASE_COUNT; p++) {
        double a = one.phases.seconds[p], b = many.phases.seconds[p];
        if (!(a >= 0.005 || b >= 0.005)) continue;
        printf("%-20s %9.2fs %9.2fs %7.2fx\n", phase_name(p), a, b, b > 0 ? a / b : 0.0);
    }
    printf("%-20s %9.2fs %9.2fs %7.2fx\n", "whole job (wall)", one.wall, many.wall, one.wall / many.wall);
    printf("%-20s %9.2fs %9.2fs\n", "whole job (CPU)", one.cpu, many.cpu);
    printf("%-20s %9.2fs %9.2fs\n", "render setup (CPU)", one.setup_cpu, many.setup_cpu);
    printf("%-20s %9.2fs %9.2fs\n", "render (CPU)", one.render_cpu, many.render_cpu);
    printf("whole job on %u threads: %.2fx the 1-thread job (goal >= %.1fx on 2 cores)\n", threads,
           one.wall / many.wall, 1.9);
    const unsigned predicted[] = {4, 8, 16};
    for (size_t i = 0; i < sizeof predicted / sizeof predicted[0]; i++) {
        double t = predict(&one, &many, threads, predicted[i]);
        printf("predicted from the phases on %2u cores: %.2fs, %.1fx\n", predicted[i], t, one.wall / t);
    }
    if (getloadavg(load, 3) >= 1) printf("load average at the end: %.2f\n", load[0]);
    plugin_registry_free(reg);
    char f[4300];
    snprintf(f, sizeof f, "%s/job.exr", out_dir), remove(f);
    snprintf(f, sizeof f, "%s/job.png", out_dir), remove(f);
    rmdir(out_dir);
    return 0;
}
