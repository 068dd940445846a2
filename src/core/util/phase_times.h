/* phase_times.h — the wall time of each phase of a job, from the scene build to the output
 * files, for the status line that `sylva render` and `sylva ztv` print and for the scaling
 * benchmark. A phase that ran several times (two ecology calls, two renders) adds up. */
#ifndef SYLVA_PHASE_TIMES_H
#define SYLVA_PHASE_TIMES_H

#include <stdio.h>

typedef enum job_phase {
    PHASE_TERRAIN,       /* the terrain plugin */
    PHASE_TREES,         /* the tree plugins' variants */
    PHASE_ECOLOGY,       /* the ecology plugin: simulated, or a saved run placed */
    PHASE_SCENE_OTHER,   /* the rest of the scene build: textures, objects, season */
    PHASE_GROUND_COVER,  /* tufts around the camera */
    PHASE_BVH,           /* Embree's acceleration structures */
    PHASE_RENDER_SETUP,  /* lights and crown proxies */
    PHASE_RENDER,        /* the pixel loop (or the ZTV grid's rays) */
    PHASE_OUTPUT,        /* writing the output files */
    PHASE_COUNT
} job_phase;

typedef struct phase_times {
    double seconds[PHASE_COUNT];
} phase_times;

/* Adds seconds to phase p; t may be NULL (nothing is kept). */
void phase_add(phase_times *t, job_phase p, double seconds);

/* Adds the time since `since` (a progress_now() value) to phase p and returns progress_now(),
 * so consecutive phases chain: `t0 = phase_since(times, PHASE_X, t0);`. t may be NULL. */
double phase_since(phase_times *t, job_phase p, double since);

/* The phase's name as printed ("tree variants"). */
const char *phase_name(job_phase p);

/* The sum of every phase. */
double phase_total(const phase_times *t);

/* One line: "phases: terrain 0.52s, tree variants 0.31s, ...; total 9.80s", phases that took no
 * time left out. */
void phase_times_print(const phase_times *t, FILE *out);

#endif
