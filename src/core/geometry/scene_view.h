/* scene_view.h — the steps a built scene takes before it is drawn from its camera (a render, a
 * POV-Ray export, a cross-check): today the ground cover near the camera for the picture's
 * size. Every command that draws the scene asks for them here, by what it makes, instead of
 * calling each step itself. */
#ifndef SYLVA_SCENE_VIEW_H
#define SYLVA_SCENE_VIEW_H

#include <stdint.h>

#include "scene/scene.h"
#include "scene/scene_settings.h"
#include "util/err.h"
#include "util/phase_times.h"

typedef struct scene_view {
    int picture;            /* 1: the scene is drawn from its camera; 0: no step is taken */
    uint32_t width, height; /* the picture's size in pixels; 0: the scene's image size */
    int quiet;              /* 1: no information line on stderr */
    unsigned threads;       /* threads for the steps that share out work; 0: one per processor */
} scene_view;

/* Takes the steps v asks for on s (gc: the scene file's ground cover), adding their times to
 * times, and says on stderr how many ground-cover tufts stand within what radius unless quiet.
 * Returns 0, or -1 with err set and its kind stated. */
int scene_view_prepare(scene *s, const ground_cover_settings *gc, const scene_view *v, phase_times *times, err_buf *err);

#endif
