/* crosscheck_result.h — what a cross-check is asked and what it finds: its options, the
 * thresholds its verdict holds to (their reasons in docs/crosscheck.md), and the result, overall
 * and per class of pixel, that crosscheck_run fills (crosscheck.h) and the report writes out
 * (crosscheck_report.h). */
#ifndef SYLVA_CROSSCHECK_RESULT_H
#define SYLVA_CROSSCHECK_RESULT_H

#include <stdint.h>

#include "crosscheck/povray_run.h"
#include "io/image_compare.h"
#include "render/film.h"

typedef struct crosscheck_thresholds {
    double min_coverage_agreement; /* share of pixels whose coverage agrees */
    double max_mae;                /* mean absolute error, all pixels and channels */
    double over_error;             /* a pixel is over when a channel differs by more than this */
    double max_over_fraction;      /* share of over pixels allowed, overall */
    double max_class_mae;          /* mean absolute error within each class that is checked */
    double min_class_share;        /* a class is checked when it covers at least this share */
} crosscheck_thresholds;

void crosscheck_default_thresholds(crosscheck_thresholds *t);

typedef struct crosscheck_options {
    uint32_t width, height, spp;  /* 0: the scene's */
    unsigned threads;             /* both renderers; 0: one per core */
    const char *povray;           /* POV-Ray's executable; NULL: SYLVA_POVRAY or "povray" */
    const char *pov_scene;        /* NULL: export the scene; else render this .pov instead (it
                                     must be an export for the same size, e.g. edited by hand) */
    const char *source;           /* the scene file's path: names the export, goes in reports */
    int quiet;                    /* no progress output */
    uint64_t outline_cutouts;     /* > 0: the scene's cut-out triangles were drawn as outlines
                                     (geometry/cutout_outline.h), this many of them, */
    uint64_t outline_triangles;   /* ... by this many opaque triangles */
    int planting_shown;           /* 1: the scene's planting plan is shown (--year), ... */
    double planting_years;        /* ... this many years after planting */
    crosscheck_thresholds thresholds;
} crosscheck_options;

typedef struct crosscheck_result {
    uint32_t width, height, spp;
    uint32_t samples;             /* camera samples per pixel both renderers take */
    char pov_scene[4200];         /* the .pov rendered */
    char pov_image[4200];         /* POV-Ray's EXR */
    char pov_log[4200];

    image_diff_stats overall;
    image_diff_stats classes[PIXEL_CLASS_COUNT];
    int class_checked[PIXEL_CLASS_COUNT];
    int class_pass[PIXEL_CLASS_COUNT];
    mask_agreement coverage;
    double coverage_mae;          /* mean |sylva coverage - POV-Ray alpha| */

    int flat_earth;               /* 1: the scene bends camera rays for the Earth's curvature, which
                                     POV-Ray's straight rays cannot; sylva rendered it flat here */
    double sylva_bvh_seconds, sylva_render_seconds, export_seconds;
    povray_result povray;
    povray_result povray_coverage; /* the second render for the alpha alone, when the scene has air */

    int pass_coverage, pass_mae, pass_over, pass_classes;
    int pass;                     /* every check holds */
    char verdict[1024];           /* a sentence: what holds, or which checks fail and by how much */
} crosscheck_result;

/* "sky", "terrain", "bark", "leaves", "objects" for pixel class k. */
const char *crosscheck_class_name(int k);

#endif
