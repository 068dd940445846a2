/* phase_times.c — adding up and printing the time of a job's phases. */
#include "util/phase_times.h"

#include "util/progress.h"

static const char *const names[PHASE_COUNT] = {
    [PHASE_TERRAIN] = "terrain",         [PHASE_TREES] = "tree variants",
    [PHASE_ECOLOGY] = "ecology",         [PHASE_SCENE_OTHER] = "rest of the scene",
    [PHASE_GROUND_COVER] = "ground cover", [PHASE_BVH] = "BVH",
    [PHASE_RENDER_SETUP] = "lights and proxies", [PHASE_RENDER] = "render",
    [PHASE_OUTPUT] = "output",
};

void phase_add(phase_times *t, job_phase p, double seconds)
{
    if (t && p < PHASE_COUNT && seconds > 0) t->seconds[p] += seconds;
}

double phase_since(phase_times *t, job_phase p, double since)
{
    double now = progress_now();
    phase_add(t, p, now - since);
    return now;
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
