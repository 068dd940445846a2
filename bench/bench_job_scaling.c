/* bench_job_scaling.c — the whole main job, scene file to output files, on 1 and on N threads:
 * each phase's wall time (the `phases:` line of `sylva render`), the job's, and the ratios, so
 * the figure on a machine with more cores can be predicted phase by phase (Amdahl: a phase that
 * speeds up by r on N threads runs the fraction p = (1 - 1/r) / (1 - 1/N) of its work in
 * parallel). Runs alternate between the thread counts so that a change in the machine's load
 * falls on both; the best of the repetitions is kept. The process CPU time of each run is printed
 * beside its wall time: on a machine shared with other work, a 1-thread run whose CPU time is
 * well under its wall time was not given a whole core, and the measured ratio is then the
 * machine's, not the code's. So it also prints each phase's time on an idle machine as its CPU
 * times give it (phase_idle_estimate: the calling thread works through every phase, so a phase
 * lasts at least the calling thread's CPU time, and at least the process's shared over the
 * threads) and the ratio and predictions from those.
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
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "util/phase_times.h"
#include "util/progress.h"

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

typedef struct job_run {
    phase_times phases; /* the render setup's CPU times go to PHASE_RENDER_SETUP, its BVH's wall time
                           to PHASE_BVH */
    double wall, cpu;
} job_run;

/* One whole job as `sylva render` runs it; 0 or -1 after printing the problem. */
static int run_job(const char *path, const plugin_registry *reg, uint32_t w, uint32_t h, uint32_t spp,
                   unsigned threads, const char *out_dir, job_run *run)
{
    memset(run, 0, sizeof *run);
    err_buf err = {{0}};
    phase_mark t0 = phase_start();
    scene_file *sf = scene_file_load(path, reg, &err);
    build_options bo = {.quiet = 1, .threads = threads, .times = &run->phases};
    scene *s = sf ? scene_build(sf, reg, &bo, &err) : NULL;
    film *f = NULL;
    int rc = -1;
    if (!s) goto done;
    /* the rest of the scene build: all of it less the phases it timed itself */
    phase_times build = {{0}};
    phase_mark t = phase_stop(&build, PHASE_SCENE_OTHER, t0);
    phase_times *ph = &run->phases;
    const job_phase timed[] = {PHASE_TERRAIN, PHASE_TREES, PHASE_ECOLOGY};
    for (size_t i = 0; i < sizeof timed / sizeof timed[0]; i++) {
        build.seconds[PHASE_SCENE_OTHER] -= ph->seconds[timed[i]];
        build.cpu[PHASE_SCENE_OTHER] -= ph->cpu[timed[i]];
        build.thread_cpu[PHASE_SCENE_OTHER] -= ph->thread_cpu[timed[i]];
    }
    ph->seconds[PHASE_SCENE_OTHER] = build.seconds[PHASE_SCENE_OTHER];
    ph->cpu[PHASE_SCENE_OTHER] = build.cpu[PHASE_SCENE_OTHER];
    ph->thread_cpu[PHASE_SCENE_OTHER] = build.thread_cpu[PHASE_SCENE_OTHER];
    if (ground_cover_add(s, &sf->ground_cover, w, h, 0, NULL, &err)) goto done;
    t = phase_stop(&run->phases, PHASE_GROUND_COVER, t);
    render_options ro = {.quiet = 1, .threads = threads, .spp = spp, .width = w, .height = h};
    render_stats st;
    render_setup *rs = render_setup_new(s, &ro, &err);
    if (!rs) goto done;
    t = phase_stop(&run->phases, PHASE_RENDER_SETUP, t);
    f = render_setup_run(rs, &ro, &st, &err);
    t = phase_stop(&run->phases, PHASE_RENDER, t);
    render_setup_free(rs);
    if (!f) goto done;
    run->phases.seconds[PHASE_RENDER_SETUP] -= st.bvh_seconds; /* the BVH's wall time on its own line */
    phase_add(&run->phases, PHASE_BVH, st.bvh_seconds);
    t = phase_start();
    char exr[4200], png[4200];
    snprintf(exr, sizeof exr, "%s/job.exr", out_dir);
    snprintf(png, sizeof png, "%s/job.png", out_dir);
    double ev = s->image.exposure_set ? s->image.exposure : auto_exposure_stops(f);
    if (film_write_exr(f, &s->site, ev, exr, &err) || film_write_png(f, png, s->image.tone, ev, &err)) goto done;
    phase_stop(&run->phases, PHASE_OUTPUT, t);
    run->wall = progress_now() - t0.wall, run->cpu = cpu_now() - t0.cpu;
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

/* Phase p's time on an idle machine on 1 and on `threads` threads, from the runs' CPU times
 * (the BVH's is in the setup's). */
static double idle(const job_run *r, job_phase p, unsigned threads)
{
    return p == PHASE_BVH ? 0 : phase_idle_estimate(&r->phases, p, threads);
}

/* The time of the job on n threads predicted from each phase's idle-machine times on 1 and on
 * n_threads threads. */
static double predict(const job_run *one, const job_run *many, unsigned n_threads, unsigned n)
{
    double total = 0;
    for (int p = 0; p < PHASE_COUNT; p++) {
        double t1 = idle(one, p, 1), tn = idle(many, p, n_threads);
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
    printf("whole job on %u threads, as measured: %.2fx the 1-thread job (goal >= %.1fx on 2 cores)\n", threads,
           one.wall / many.wall, 1.9);

    /* The same from CPU times: what an idle machine would show (phase_idle_estimate). */
    printf("\non an idle machine, from the CPU times (1 thread: its CPU time; %u: the longer of the\n"
           "calling thread's CPU time and the process's over %u):\n", threads, threads);
    printf("%-20s %10s %10s %8s\n", "phase", "1 thread", "threads", "ratio");
    double sum_one = 0, sum_many = 0;
    for (int p = 0; p < PHASE_COUNT; p++) {
        double a = idle(&one, p, 1), b = idle(&many, p, threads);
        sum_one += a, sum_many += b;
        if (!(a >= 0.005 || b >= 0.005)) continue;
        printf("%-20s %9.2fs %9.2fs %7.2fx\n", p == PHASE_RENDER_SETUP ? "BVH, lights, proxies" : phase_name(p), a, b,
               b > 0 ? a / b : 0.0);
    }
    printf("%-20s %9.2fs %9.2fs %7.2fx\n", "whole job", sum_one, sum_many, sum_one / sum_many);
    printf("whole job on %u idle cores: %.2fx the 1-thread job (goal >= %.1fx on 2 cores)\n", threads,
           sum_one / sum_many, 1.9);
    const unsigned predicted[] = {4, 8, 16};
    for (size_t i = 0; i < sizeof predicted / sizeof predicted[0]; i++) {
        double t = predict(&one, &many, threads, predicted[i]);
        printf("predicted from the phases on %2u idle cores: %.2fs, %.1fx\n", predicted[i], t, sum_one / t);
    }
    if (getloadavg(load, 3) >= 1) printf("load average at the end: %.2f\n", load[0]);
    plugin_registry_free(reg);
    char f[4300];
    snprintf(f, sizeof f, "%s/job.exr", out_dir), remove(f);
    snprintf(f, sizeof f, "%s/job.png", out_dir), remove(f);
    rmdir(out_dir);
    return 0;
}
