/* crosscheck.h — the cross-check: one scene rendered by sylva's verification mode and by
 * POV-Ray from its export (io/pov_write.h), compared in linear float.
 *
 * sylva's picture is the reference; POV-Ray's EXR (rendered with an alpha channel that is 0
 * where the sky shows) is composited over the sky colour of the export to give the same
 * picture. Measured: coverage agreement (the share of pixels that both call covered, or both
 * call sky, at half coverage; sylva's coverage is its share of camera samples that hit a
 * surface, POV-Ray's its alpha), and over RGB: mean absolute error, RMSE, PSNR, the largest
 * error and the share of pixels with an error over a threshold — overall and per class of
 * what the pixel's centre ray sees (terrain, bark, leaves, objects, sky; render/film.h).
 * The thresholds and their reasons are in docs/crosscheck.md. A scene with earth.curvature on
 * is compared as if the Earth were flat (sylva's rays straight too), and the result says so.
 *
 * Files written into the output folder: sylva.exr and sylva.png (the verification render),
 * povray.png (POV-Ray's picture, tone-mapped alike), difference.png (heatmap of the largest
 * channel error, black 0 to white at full scale), classes.png (the class of each pixel),
 * report.html and metrics.json (crosscheck_report.h); with an export also the .pov and its
 * include files, POV-Ray's EXR and its log. Progress goes to stderr unless quiet. */
#ifndef SYLVA_CROSSCHECK_H
#define SYLVA_CROSSCHECK_H

#include <stdint.h>

#include "crosscheck/povray_run.h"
#include "io/image_compare.h"
#include "render/film.h"
#include "scene/scene.h"
#include "util/err.h"

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

    int pass_coverage, pass_mae, pass_over, pass_classes;
    int pass;                     /* every check holds */
    char verdict[1024];           /* a sentence: what holds, or which checks fail and by how much */
} crosscheck_result;

enum { CROSSCHECK_FAILED = -1, CROSSCHECK_NOT_WRITTEN = -2 };

/* Runs the cross-check of s into out_dir (created when missing; its parent must exist).
 * Returns 0 when both renders were compared (r->pass tells whether the thresholds hold);
 * CROSSCHECK_NOT_WRITTEN with err set when an output file or folder could not be written;
 * CROSSCHECK_FAILED with err set when something else could not be done (POV-Ray missing or
 * failing, sizes that do not match, out of memory). */
int crosscheck_run(const scene *s, const char *out_dir, const crosscheck_options *o, crosscheck_result *r,
                   err_buf *err);

/* "sky", "terrain", "bark", "leaves", "objects" for pixel class k. */
const char *crosscheck_class_name(int k);

#endif
