/* study_frames.h — the frames a study renders each product in (docs/study.md, Frames), their
 * lens and their size in pixels:
 *
 *   single          a 50 mm lens on a 36 x 24 mm (full-frame) sensor in landscape: 39.6 x 27.0
 *                   degrees, pages 3:2
 *   planar_53       53.5 degrees across on a plane, on a page 820 x 260 mm: 18.2 degrees down
 *   cylindrical_90  a cylindrical panorama 90 degrees across, on the same 820 x 260 mm page
 *
 * A frame keeps a viewpoint's place, direction, up and roll and replaces its lens. Its size: the
 * study's [width, height] when both are given (every frame then that size, its vertical field
 * following from it); else a width of the study's width when given (a height of 0), else of
 * print_width / 25.4 * dpi pixels when a print width is given, else the scene's image width, and
 * the height that keeps the frame's page (width times its aspect, rounded). */
#ifndef SYLVA_STUDY_FRAMES_H
#define SYLVA_STUDY_FRAMES_H

#include <stdint.h>

#include "scene/scene_settings.h"

typedef struct study_frame_def {
    const char *name;        /* as the scene file and the outputs name it */
    int cylindrical;         /* 0: planar (a pinhole) */
    double focal_length_mm;  /* on a 36 mm sensor; 0: fov_deg given */
    double fov_deg;          /* across */
    double aspect;           /* the page's height over its width */
} study_frame_def;

/* The definition of frame f (a study_frame). */
const study_frame_def *study_frame_of(int f);

/* How a study's frames are sized (study_settings, with the command line's overrides). */
typedef struct study_sizing {
    uint32_t size[2];        /* [width, height] of every frame; [width, 0]: the width alone; 0, 0:
                                not given */
    double print_width_mm;   /* 0: not given */
    double dpi;
    uint32_t image_width;    /* the scene's image width */
} study_sizing;

/* The pixels of frame f: out[0] wide, out[1] high. */
void study_frame_size(int f, const study_sizing *z, uint32_t out[2]);

/* c with the lens of frame f: its projection and field of view. */
void study_frame_lens(int f, camera_settings *c);

#endif
