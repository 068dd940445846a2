/* study_job.h — one viewpoint of a study in one frame: the viewpoint's camera placed over the
 * built scene (its eye height above the ground), the ground cover for that camera and size
 * (geometry/scene_view.h), one render setup (Embree's BVH and crown proxies, which follow the
 * camera; the lights, which ro's lights cache keeps for every camera that sees the same sky) for
 * every product, the scene rendered with its development and, when the existing
 * view or the wireline is asked for, without it (the same setup and samples, as a montage's
 * pair), then the products written and the scene left as it was built (its ground cover taken
 * out, scene/scene_mark.h).
 *
 * The proposed view is written as `sylva render --viewpoint NAME --size WxH` writes its frame,
 * through the same calls on the same scene, so the two files are byte for byte the same. The
 * existing view and the wireline take the proposed view's exposure (metered on it, or the
 * scene's image.exposure), so that the development is the only difference between them. The
 * wireline is the existing view's PNG with the development's outline in red and its inner
 * edges in yellow (render/wireline.h), its EXR the existing view's layers with the
 * development's coverage and radiance from the proposed one. */
#ifndef SYLVA_STUDY_JOB_H
#define SYLVA_STUDY_JOB_H

#include <stdint.h>

#include "render/render.h"
#include "scene/scene.h"
#include "scene_file/scene_file.h"
#include "page/page.h"
#include "study/study_manifest.h"
#include "util/err.h"
#include "util/phase_times.h"

#define STUDY_PATH_MAX 4096

typedef struct study_job {
    const scene_viewpoint *view;
    int frame;                       /* a study_frame */
    uint32_t size[2];                /* pixels */
    camera_settings camera;          /* the viewpoint's, with the frame's lens */
    unsigned todo;                   /* the products to render: bits 1u << study_product */
    int part;                        /* the part of the run that renders it (util/run_parts.h) */
    char record[STUDY_PRODUCTS][STUDY_MANIFEST_MAX]; /* each product's record (study_manifest.h) */
    char folder[STUDY_PATH_MAX];     /* DIR/VIEWPOINT */
    page_size page;                  /* the sheet's page (sheet/sheet.h) */
    char other_frames[64];           /* the study's frames but this one, for the sheet; "" when none */
} study_job;

/* The file of product p of j with extension ext ("png", "exr", "manifest"): FOLDER/PRODUCT_FRAME.EXT.
 * Returns 0, or -1 with err set when it does not fit. */
int study_job_path(const study_job *j, int p, const char *ext, char out[STUDY_PATH_MAX], err_buf *err);

/* The extension of product p's second file beside its PNG: "exr", or "pdf" for the sheet. */
const char *study_product_ext(int p);

/* The products of `todo` that need the view without the development rendered. */
#define STUDY_NEEDS_PAIR (1u << STUDY_EXISTING | 1u << STUDY_WIRELINE | 1u << STUDY_SHEET)

/* Checks that j's camera can be placed over s's ground (its eye height above the terrain), so that
 * a viewpoint off the terrain is refused before any image is rendered. Returns 0, or -1 with err
 * set at the viewpoint. s's camera is left as j's. */
int study_job_place(scene *s, const scene_file *sf, const study_job *j, err_buf *err);

/* Renders j on s (built from sf) with ro's threads and samples and writes its products, adding
 * the phases to times and the renders made to *renders. s is the same after as before. Returns 0,
 * or -1 with err set (a camera off the terrain located at the viewpoint, an output not written). */
int study_job_run(scene *s, const scene_file *sf, const study_job *j, const render_options *ro, phase_times *times,
                  uint32_t *renders, err_buf *err);

#endif
