/* phase_times.h — the wall time of each phase of a job, from the scene build to the output
 * files, for the status line that `sylva render` and `sylva ztv` print and for the scaling
 * benchmark. A phase that ran several times (two ecology calls, two renders) adds up. */
#ifndef SYLVA_PHASE_TIMES_H
#define SYLVA_PHASE_TIMES_H

#include <stdio.h>

typedef enum job_phase {
    PHASE_LIBRARIES,     /* before the command's work: the dynamic loader mapping and relocating
                          * the shared libraries, their initialisers, the options (CPU time) */
    PHASE_PLUGINS,       /* the plugin registry: manifests read, nothing run */
    PHASE_SCENE_FILE,    /* the scene file read and checked (a site's CRS and DTM through PROJ
                          * and GDAL included) */
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
    double seconds[PHASE_COUNT];    /* wall time */
    double cpu[PHASE_COUNT];        /* the process's CPU time, every thread's (0: not measured) */
    double thread_cpu[PHASE_COUNT]; /* the CPU time of the thread that ran the phase, a worker too */
} phase_times;

/* When a phase started: the clocks phase_stop reads. */
typedef struct phase_mark {
    double wall, cpu, thread_cpu;
} phase_mark;

/* Adds wall seconds to phase p; t may be NULL (nothing is kept). */
void phase_add(phase_times *t, job_phase p, double seconds);

/* The clocks now. */
phase_mark phase_start(void);

/* Adds the wall, process CPU and calling thread's CPU time since m to phase p and returns
 * phase_start(), so consecutive phases chain: `m = phase_stop(times, PHASE_X, m);`. t may be
 * NULL. */
phase_mark phase_stop(phase_times *t, job_phase p, phase_mark m);

/* The wall time phase p would take on an otherwise idle machine, from its CPU times on `threads`
 * threads: the longer of the calling thread's CPU time (it works through the phase, so the
 * phase lasts at least that) and the process's CPU time shared over the threads. Its wall time
 * when no CPU time was measured. On a machine busy with other work, wall times are the
 * machine's; this is the code's. */
double phase_idle_estimate(const phase_times *t, job_phase p, unsigned threads);

/* The phase's name as printed ("tree variants"). */
const char *phase_name(job_phase p);

/* The sum of every phase. */
double phase_total(const phase_times *t);

/* One line: "phases: terrain 0.52s, tree variants 0.31s, ...; total 9.80s", phases that took no
 * time left out. */
void phase_times_print(const phase_times *t, FILE *out);

#endif
