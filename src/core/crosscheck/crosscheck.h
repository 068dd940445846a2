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
 * include files, POV-Ray's EXR and its log. Progress goes to stderr unless quiet. The options,
 * thresholds and result are in crosscheck_result.h. */
#ifndef SYLVA_CROSSCHECK_H
#define SYLVA_CROSSCHECK_H

#include "crosscheck/crosscheck_result.h"
#include "scene/scene.h"
#include "util/err.h"

enum { CROSSCHECK_FAILED = -1, CROSSCHECK_NOT_WRITTEN = -2 };

/* Runs the cross-check of s into out_dir (created when missing; its parent must exist).
 * Returns 0 when both renders were compared (r->pass tells whether the thresholds hold);
 * CROSSCHECK_NOT_WRITTEN with err set when an output file or folder could not be written;
 * CROSSCHECK_FAILED with err set when something else could not be done (POV-Ray missing or
 * failing, sizes that do not match, out of memory). */
int crosscheck_run(const scene *s, const char *out_dir, const crosscheck_options *o, crosscheck_result *r,
                   err_buf *err);

#endif
