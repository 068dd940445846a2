/* povray_run.h — running POV-Ray 3.7 on an exported scene the way the cross-check needs it:
 * linear half-float EXR output with an alpha channel that is 0 where the sky shows, the
 * antialiasing that matches sylva's verification samples (render/integrator.h: non-adaptive
 * method 1, threshold 0, no jitter, R x R sub-samples plus the pixel centre), no display.
 *
 * POV-Ray runs in the scene's folder (its default I/O restrictions allow reading and writing
 * there, and it looks for include and image files there), with its messages sent to a log
 * file in that folder. The executable is `povray` on the PATH unless the job names another or
 * the environment variable SYLVA_POVRAY does. Nothing here prints. */
#ifndef SYLVA_POVRAY_RUN_H
#define SYLVA_POVRAY_RUN_H

#include <stdint.h>

#include "util/err.h"

typedef struct povray_job {
    const char *folder;     /* where the scene is; POV-Ray runs there */
    const char *scene;      /* the .pov file's name within folder */
    const char *output;     /* the EXR to write, a name within folder */
    const char *log;        /* the file (within folder) that receives POV-Ray's messages */
    const char *executable; /* NULL: $SYLVA_POVRAY, else "povray" */
    uint32_t width, height, spp;
    unsigned threads;       /* render threads; 0: POV-Ray's default (one per core) */
    int no_air;             /* 1: declare Sylva_no_air=1 and Sylva_coverage_only=1 (the export's fog
                               and sun left out: a render for its alpha alone) */
} povray_job;

typedef struct povray_result {
    double wall_seconds;    /* the whole process */
    double parse_seconds;   /* POV-Ray's own figures from its log; -1 when not found */
    double bounding_seconds;
    double trace_seconds;
    double parse_cpu_seconds; /* the CPU time POV-Ray's log gives for parsing and tracing; -1 */
    double trace_cpu_seconds; /* when not found */
    double cpu_seconds;     /* the process's user and system time */
    int exit_status;        /* POV-Ray's exit status */
} povray_result;

/* The antialiasing options matching sylva's verification samples for spp: "-A" below 4 spp,
 * else "+A0.0 +AM1 +R<n> -J" with n = floor(sqrt(spp)). out holds at least 32 bytes. */
void povray_antialias_options(uint32_t spp, char *out, size_t n);

/* Renders the job; returns 0 when POV-Ray ran and exited with status 0, else -1 with err set
 * (not found, failed to start, or failed: the message then quotes the log's error lines). */
int povray_render(const povray_job *job, povray_result *res, err_buf *err);

#endif
