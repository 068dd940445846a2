/* phase_times.c — adding up and printing the time of a job's phases. */
#include "util/phase_times.h"

#include <time.h>

#include "util/progress.h"

static const char *const names[PHASE_COUNT] = {
    [PHASE_LIBRARIES] = "libraries",     [PHASE_PLUGINS] = "plugins",
    [PHASE_SCENE_FILE] = "scene file",   [PHASE_TERRAIN] = "terrain",         [PHASE_TREES] = "tree variants",
    [PHASE_ECOLOGY] = "ecology",         [PHASE_SCENE_OTHER] = "rest of the scene",
    [PHASE_GROUND_COVER] = "ground cover", [PHASE_BVH] = "BVH",
    [PHASE_RENDER_SETUP] = "lights and proxies", [PHASE_RENDER] = "render",
    [PHASE_OUTPUT] = "output",
};

void phase_add(phase_times *t, job_phase p, double seconds)
{
    if (t && p < PHASE_COUNT && seconds > 0) t->seconds[p] += seconds;
}

static double clock_seconds(clockid_t id)
{
    struct timespec ts;
    clock_gettime(id, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

phase_mark phase_start(void)
{
    return (phase_mark){progress_now(), clock_seconds(CLOCK_PROCESS_CPUTIME_ID), clock_seconds(CLOCK_THREAD_CPUTIME_ID)};
}

phase_mark phase_stop(phase_times *t, job_phase p, phase_mark m)
{
    phase_mark now = phase_start();
    if (t && p < PHASE_COUNT) {
        phase_add(t, p, now.wall - m.wall);
        t->cpu[p] += now.cpu - m.cpu;
        t->thread_cpu[p] += now.thread_cpu - m.thread_cpu;
    }
    return now;
}

double phase_idle_estimate(const phase_times *t, job_phase p, unsigned threads)
{
    if (p >= PHASE_COUNT) return 0;
    if (!(t->cpu[p] > 0)) return t->seconds[p];
    double shared = t->cpu[p] / (threads ? threads : 1);
    return t->thread_cpu[p] > shared ? t->thread_cpu[p] : shared;
}

const char *phase_name(job_phase p) { return p < PHASE_COUNT ? names[p] : "?"; }

double phase_total(const phase_times *t)
{
    double sum = 0;
    for (int p = 0; p < PHASE_COUNT; p++) sum += t->seconds[p];
    return sum;
}

void phase_times_print(const phase_times *t, FILE *out)
{
    fprintf(out, "phases:");
    const char *sep = " ";
    for (int p = 0; p < PHASE_COUNT; p++) {
        if (!(t->seconds[p] >= 0.005)) continue;
        fprintf(out, "%s%s %.2fs", sep, names[p], t->seconds[p]);
        sep = ", ";
    }
    fprintf(out, "; total %.2fs\n", phase_total(t));
}
