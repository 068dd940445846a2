/* crosscheck_report.h — the cross-check's report: report.html (the two pictures side by side,
 * the difference heatmap, the class map, metrics overall and per class, coverage, thresholds
 * and both renderers' timing) and metrics.json (the same figures for programs; a number that
 * is infinite, such as the PSNR of identical pictures, is null). Both are written under a
 * temporary name and renamed into place. */
#ifndef SYLVA_CROSSCHECK_REPORT_H
#define SYLVA_CROSSCHECK_REPORT_H

#include "crosscheck/crosscheck_result.h"
#include "util/err.h"

/* Writes out_dir/report.html and out_dir/metrics.json for r; heatmap_scale is the error at
 * which difference.png turns white. Returns 0 or -1 with err set. */
int crosscheck_write_report(const char *out_dir, const crosscheck_result *r, const crosscheck_options *o,
                            double heatmap_scale, err_buf *err);

#endif
