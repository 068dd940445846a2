/* render_still.h — `sylva render`'s pipeline on a built scene: the path-traced frame, metered
 * and written as the PNG and EXR pair, with the information lines a render prints. Split
 * between the parts of a job (util/run_parts.h): each part renders its bands of rows and part
 * 0 gathers them, meters the exposure and writes the files. */
#ifndef SYLVA_RENDER_STILL_H
#define SYLVA_RENDER_STILL_H

#include "render/render.h"
#include "scene/scene.h"
#include "util/err.h"
#include "util/phase_times.h"
#include "util/run_parts.h"

typedef struct render_still_options {
    render_options render; /* its part and parts are set from the run's parts */
    const char *png, *exr; /* the outputs */
    double started;        /* progress_now() when the command began: the total time's start */
    double scene_seconds;  /* to load and build the scene */
} render_still_options;

/* The exposure in stops a still of sc is written with: the scene's image.exposure when given,
 * else metered on f (render/auto_exposure.h). */
double render_still_exposure(const scene *sc, const film *f);

/* Renders sc and writes the pair (part 0), adding the phases to times. Returns 0, or -1 with err
 * set (its kind stated), or -1 with err empty when another part failed. */
int render_still_run(const scene *sc, const render_still_options *o, const run_parts *parts, phase_times *times,
                     err_buf *err);

#endif
