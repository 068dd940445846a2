/* study_run.h — `sylva study`: every viewpoint's products from one build of the scene
 * (docs/study.md).
 *
 * The study is planned first: its viewpoints (study_views.h), for each the frames and the
 * products asked for, and for each product its files DIR/VIEWPOINT/PRODUCT_FRAME.png and .exr
 * and its record (study_manifest.h). A product whose files are there and whose record matches
 * is kept; when every product is kept nothing is built. Otherwise the scene is built once —
 * terrain, vegetation, objects — with the rendered ground refined around the development
 * rather than around a camera (build_options.detail_at_development), so one ground serves every
 * viewpoint; then each viewpoint in each frame is rendered as one job (study_job.h), in rank
 * order, with a line of progress and the study's time left after each.
 *
 * With the scene's ztv: section (or the product ztv asked for) the study's visibility map is made
 * once from the same build, after the views, into DIR/ztv/ (study_ztv.h).
 *
 * Split between the parts of a job (an MPI job, util/run_parts.h), each part builds the scene
 * and renders whole jobs, shared by their samples (frame pixels times spp, twice for a pair):
 * the largest first, each to the part with the least work so far, so every part computes the
 * same sharing; each part renders its jobs in rank order. The parts agree once after planning,
 * so no part writes before every part has planned; each part writes its own jobs' files.
 *
 * The scene file is borrowed; the scene built is freed before study_run returns. */
#ifndef SYLVA_STUDY_RUN_H
#define SYLVA_STUDY_RUN_H

#include <stdint.h>

#include "plugin/plugin_host.h"
#include "scene_build/build_options.h"
#include "scene_file/scene_file.h"
#include "study/study_views.h"
#include "study/study_ztv.h"
#include "util/err.h"
#include "util/phase_times.h"
#include "util/run_parts.h"

typedef struct study_options {
    const char *dir;              /* the output folder (made when missing; its parent must exist) */
    study_view_names names;       /* --viewpoints, --only, --rank */
    const char *products, *frames; /* names separated by commas or spaces; NULL: the study: section's */
    uint32_t size[2];             /* pixels of every frame; [width, 0]: the width, each frame's own
                                     height; 0, 0: the section's */
    double print_width_mm;        /* > 0: the frames' width in print (with dpi); 0: the section's */
    double dpi;                   /* > 0: in place of the section's */
    uint32_t spp;                 /* 0: the section's, else the image's */
    int force;                    /* 1: render every product, kept or not */
    build_options build;          /* threads, quiet, verbose; its ground is set here */
    study_ztv ztv;                /* how the study's visibility map is made (study_ztv.h) */
} study_options;

typedef struct study_report {
    uint32_t viewpoints, jobs;    /* viewpoints; viewpoints times frames */
    uint32_t products;            /* products planned (on every part) */
    uint32_t kept;                /* of which up to date and kept */
    uint32_t rendered;            /* written by this part */
    uint32_t renders, builds;     /* frames rendered and scenes built by this part */
    int ztv;                      /* the visibility map: 0 not asked for, 1 made, 2 up to date and kept */
    double build_seconds, seconds;
    phase_times times;            /* this part's */
} study_report;

/* Runs the study of sf with o (plugins from reg) as part parts->part of parts->parts, filling
 * rep. Returns 0, or -1 with err set (its kind stated), or -1 with err empty when another part
 * failed. */
int study_run(scene_file *sf, const plugin_registry *reg, const study_options *o, const run_parts *parts,
              study_report *rep, err_buf *err);

#endif
