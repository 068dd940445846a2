/* crosscheck_report.c — report.html and metrics.json. */
#include "crosscheck/crosscheck_report.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "io/atomic_file.h"
#include "util/html_text.h"
#include "util/json_text.h"

/* ------------------------------------------------------------------------------------------ */
/* shared                                                                                      */

/* POV-Ray's parse + trace time over sylva's BVH + render time, or -1 when unknown. */
static double time_ratio(const crosscheck_result *r)
{
    double pov = r->povray.parse_seconds + r->povray.trace_seconds;
    double syl = r->sylva_bvh_seconds + r->sylva_render_seconds;
    if (r->povray.parse_seconds < 0 || r->povray.trace_seconds < 0 || !(syl > 0)) return -1.0;
    return pov / syl;
}

static const char *file_name(const char *path)
{
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}

/* ------------------------------------------------------------------------------------------ */
/* metrics.json                                                                                */


static void json_number(FILE *f, double v)
{
    if (isfinite(v)) fprintf(f, "%.9g", v);
    else fputs("null", f);
}

static void json_stats(FILE *f, const image_diff_stats *d)
{
    fprintf(f, "{\"pixels\": %llu, \"mae\": ", (unsigned long long)d->pixels);
    json_number(f, d->mae);
    fputs(", \"rmse\": ", f);
    json_number(f, d->rmse);
    fputs(", \"psnr\": ", f);
    json_number(f, d->psnr);
    fputs(", \"max\": ", f);
    json_number(f, d->max_abs);
    fputs(", \"over_fraction\": ", f);
    json_number(f, d->over_fraction);
    fprintf(f, ", \"over_pixels\": %llu, \"nonfinite_pixels\": %llu", (unsigned long long)d->over_pixels,
            (unsigned long long)d->nonfinite_pixels);
}

static int write_json(const char *out_dir, const crosscheck_result *r, const crosscheck_options *o, err_buf *err)
{
    char path[4300];
    atomic_file out;
    snprintf(path, sizeof path, "%s/metrics.json", out_dir);
    FILE *f = atomic_file_open_stream(&out, path, err);
    if (!f) return -1;
    const crosscheck_thresholds *t = &o->thresholds;
    fputs("{\n  \"scene\": ", f);
    json_write_string(f, o->source);
    fputs(",\n  \"povray_scene\": ", f);
    json_write_string(f, r->pov_scene);
    fprintf(f, ",\n  \"width\": %u, \"height\": %u, \"spp\": %u, \"samples_per_pixel\": %u,\n", r->width, r->height,
            r->spp, r->samples);
    fprintf(f, "  \"flat_earth\": %s,\n", r->flat_earth ? "true" : "false");
    fprintf(f, "  \"leaves\": \"%s\", \"outlined_cutout_triangles\": %llu, \"outline_triangles\": %llu,\n",
            o->outline_cutouts ? "outline" : "mask", (unsigned long long)o->outline_cutouts,
            (unsigned long long)o->outline_triangles);
    if (o->planting_shown) fprintf(f, "  \"planting_year\": %.17g,\n", o->planting_years);
    else fputs("  \"planting_year\": null,\n", f);
    fprintf(f, "  \"pass\": %s,\n  \"verdict\": ", r->pass ? "true" : "false");
    json_write_string(f, r->verdict);
    fprintf(f, ",\n  \"checks\": {\"coverage\": %s, \"mae\": %s, \"over\": %s, \"classes\": %s},\n",
            r->pass_coverage ? "true" : "false", r->pass_mae ? "true" : "false", r->pass_over ? "true" : "false",
            r->pass_classes ? "true" : "false");
    fputs("  \"thresholds\": {\"min_coverage_agreement\": ", f);
    json_number(f, t->min_coverage_agreement);
    fputs(", \"max_mae\": ", f);
    json_number(f, t->max_mae);
    fputs(", \"over_error\": ", f);
    json_number(f, t->over_error);
    fputs(", \"max_over_fraction\": ", f);
    json_number(f, t->max_over_fraction);
    fputs(", \"max_class_mae\": ", f);
    json_number(f, t->max_class_mae);
    fputs(", \"min_class_share\": ", f);
    json_number(f, t->min_class_share);
    fputs("},\n  \"coverage\": {\"agreement\": ", f);
    json_number(f, r->coverage.agreement);
    fputs(", \"overlap\": ", f);
    json_number(f, r->coverage.overlap);
    fprintf(f, ", \"both\": %llu, \"only_sylva\": %llu, \"only_povray\": %llu, \"neither\": %llu, \"mae\": ",
            (unsigned long long)r->coverage.both, (unsigned long long)r->coverage.only_ref,
            (unsigned long long)r->coverage.only_test, (unsigned long long)r->coverage.neither);
    json_number(f, r->coverage_mae);
    fputs("},\n  \"overall\": ", f);
    json_stats(f, &r->overall);
    fputs("},\n  \"classes\": {\n", f);
    for (int k = 0; k < PIXEL_CLASS_COUNT; k++) {
        fprintf(f, "    \"%s\": ", crosscheck_class_name(k));
        json_stats(f, &r->classes[k]);
        fprintf(f, ", \"checked\": %s, \"pass\": %s}%s\n", r->class_checked[k] ? "true" : "false",
                r->class_pass[k] ? "true" : "false", k + 1 < PIXEL_CLASS_COUNT ? "," : "");
    }
    /* POV-Ray's figures are -1 when its log did not give them: null */
    double ratio = time_ratio(r);
    const struct { const char *name; double value; } timing[] = {
        {"sylva_bvh_seconds", r->sylva_bvh_seconds},
        {"sylva_render_seconds", r->sylva_render_seconds},
        {"export_seconds", r->export_seconds},
        {"povray_parse_seconds", r->povray.parse_seconds},
        {"povray_bounding_seconds", r->povray.bounding_seconds},
        {"povray_trace_seconds", r->povray.trace_seconds},
        {"povray_wall_seconds", r->povray.wall_seconds},
        {"povray_parse_cpu_seconds", r->povray.parse_cpu_seconds},
        {"povray_trace_cpu_seconds", r->povray.trace_cpu_seconds},
        {"povray_cpu_seconds", r->povray.cpu_seconds},
        {"povray_coverage_cpu_seconds", r->povray_coverage.cpu_seconds},
        {"povray_over_sylva", ratio},
    };
    fputs("  },\n  \"timing\": {", f);
    for (size_t k = 0; k < sizeof timing / sizeof *timing; k++) {
        fprintf(f, "%s\"%s\": ", k ? ", " : "", timing[k].name);
        json_number(f, timing[k].value >= 0 ? timing[k].value : NAN);
    }
    fputs("},\n  \"files\": {\"sylva\": \"sylva.exr\", \"povray\": ", f);
    json_write_string(f, r->pov_image);
    fputs(", \"povray_log\": ", f);
    json_write_string(f, r->pov_log);
    fputs(", \"difference\": \"difference.png\", \"classes\": \"classes.png\", \"report\": \"report.html\"}\n}\n", f);
    return atomic_file_commit(&out, err);
}

/* ------------------------------------------------------------------------------------------ */
/* report.html                                                                                 */

static void html_stats_row(FILE *f, const char *label, const image_diff_stats *d, uint64_t total, const char *result)
{
    fprintf(f, "<tr><td>%s</td><td>%llu</td><td>", label, (unsigned long long)d->pixels);
    html_number(f, total ? 100.0 * d->pixels / total : 0.0, "%.1f %%");
    fputs("</td><td>", f);
    html_number(f, d->mae, "%.3g");
    fputs("</td><td>", f);
    html_number(f, d->rmse, "%.3g");
    fputs("</td><td>", f);
    html_number(f, d->psnr, "%.1f dB");
    fputs("</td><td>", f);
    html_number(f, d->max_abs, "%.3g");
    fputs("</td><td>", f);
    html_number(f, 100 * d->over_fraction, "%.3f %%");
    fprintf(f, "</td><td>%s</td></tr>\n", result);
}

static void html_seconds(FILE *f, const char *label, double s)
{
    fprintf(f, "<tr><td>%s</td><td>", label);
    if (s >= 0) fprintf(f, "%.3f s", s);
    else fputs("not reported", f);
    fputs("</td></tr>\n", f);
}

static int write_html(const char *out_dir, const crosscheck_result *r, const crosscheck_options *o,
                      double heatmap_scale, err_buf *err)
{
    char path[4300];
    atomic_file out;
    snprintf(path, sizeof path, "%s/report.html", out_dir);
    FILE *f = atomic_file_open_stream(&out, path, err);
    if (!f) return -1;
    const crosscheck_thresholds *t = &o->thresholds;
    uint64_t n = (uint64_t)r->width * r->height;
    fputs("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>sylva / POV-Ray cross-check: ", f);
    html_text(f, file_name(o->source ? o->source : r->pov_scene));
    fputs("</title>\n<style>\n"
          "body { font-family: sans-serif; margin: 1.5em; color: #222; }\n"
          "table { border-collapse: collapse; margin: 0.5em 0 1.5em; }\n"
          "td, th { border: 1px solid #bbb; padding: 0.25em 0.6em; text-align: right; }\n"
          "td:first-child, th:first-child { text-align: left; }\n"
          "figure { display: inline-block; margin: 0 1em 1em 0; vertical-align: top; }\n"
          "figure img { image-rendering: pixelated; min-width: 320px; border: 1px solid #888; }\n"
          ".pass { background: #d9f2d9; padding: 0.6em; } .fail { background: #f8d7d7; padding: 0.6em; }\n"
          "</style>\n</head>\n<body>\n<h1>sylva / POV-Ray cross-check</h1>\n<p>Scene: <code>", f);
    html_text(f, o->source ? o->source : "(none given)");
    fputs("</code>; POV-Ray scene: <code>", f);
    html_text(f, r->pov_scene);
    fprintf(f, "</code>; %u &times; %u pixels, %u spp (%u camera samples per pixel in both renderers: the pixel "
               "centre and a regular grid, no jitter).</p>\n<p class=\"%s\"><strong>%s</strong> &mdash; ",
            r->width, r->height, r->spp, r->samples, r->pass ? "pass" : "fail", r->pass ? "PASS" : "FAIL");
    html_text(f, r->verdict);
    fputs("</p>\n<h2>Pictures</h2>\n"
          "<figure><img src=\"sylva.png\" alt=\"sylva\"><figcaption>sylva, verification mode</figcaption></figure>\n"
          "<figure><img src=\"povray.png\" alt=\"POV-Ray\"><figcaption>POV-Ray 3.7, over the sky colour</figcaption></figure>\n",
          f);
    fprintf(f, "<figure><img src=\"difference.png\" alt=\"difference\"><figcaption>largest channel error: black 0, "
               "red, yellow, white at %.3g and more; magenta not finite</figcaption></figure>\n"
               "<figure><img src=\"classes.png\" alt=\"classes\"><figcaption>classes: sky (light blue), terrain "
               "(ochre), bark (brown), leaves (green), objects (light grey)</figcaption></figure>\n",
            heatmap_scale);
    if (r->flat_earth)
        fputs("<p>The scene bends its camera rays for the Earth's curvature and refraction "
              "(<code>earth.curvature</code>); POV-Ray's rays are straight, so both pictures here show "
              "the scene on a flat Earth, and <code>sylva render</code> of this scene differs from them "
              "(docs/models/curvature.md).</p>\n", f);
    if (o->outline_cutouts)
        fprintf(f, "<p>The scene's alpha-masked leaves were drawn by both renderers as opaque outline polygons "
                   "(<code>--leaves outline</code>): %llu cut-out triangles replaced by %llu, so POV-Ray does not "
                   "continue its rays through each transparent texel. The leaves' shapes are coarser than the "
                   "path tracer's; the renderers are compared on the same surfaces (docs/crosscheck.md).</p>\n",
                (unsigned long long)o->outline_cutouts, (unsigned long long)o->outline_triangles);
    if (o->planting_shown)
        fprintf(f, "<p>The scene's planting plan is shown %g years after planting (<code>--year</code>): its "
                   "plants grown to their age then, its fellings made (docs/mitigation.md).</p>\n",
                o->planting_years);
    fputs("<p>Both pictures are tone-mapped alike for viewing; every metric is computed on linear float values "
          "(sylva's EXR and POV-Ray's half-float EXR).</p>\n", f);

    fputs("<h2>Metrics</h2>\n<table>\n<tr><th>pixels</th><th>count</th><th>share</th><th>MAE</th><th>RMSE</th>"
          "<th>PSNR</th><th>max</th>", f);
    fprintf(f, "<th>over %.3g</th><th>result</th></tr>\n", t->over_error);
    html_stats_row(f, "all", &r->overall, n, r->pass_mae && r->pass_over ? "pass" : "fail");
    for (int k = 0; k < PIXEL_CLASS_COUNT; k++)
        html_stats_row(f, crosscheck_class_name(k), &r->classes[k], n,
                       !r->class_checked[k] ? "not checked" : r->class_pass[k] ? "pass" : "fail");
    fputs("</table>\n", f);
    fputs("<h2>Coverage</h2>\n<table>\n<tr><th>measure</th><th>value</th></tr>\n<tr><td>agreement</td><td>", f);
    html_number(f, 100 * r->coverage.agreement, "%.3f %%");
    fputs("</td></tr>\n<tr><td>overlap (Jaccard)</td><td>", f);
    html_number(f, r->coverage.overlap, "%.5f");
    fprintf(f, "</td></tr>\n<tr><td>covered in both</td><td>%llu</td></tr>\n<tr><td>covered in sylva only</td><td>%llu</td></tr>\n"
               "<tr><td>covered in POV-Ray only</td><td>%llu</td></tr>\n<tr><td>sky in both</td><td>%llu</td></tr>\n"
               "<tr><td>mean |coverage &minus; alpha|</td><td>",
            (unsigned long long)r->coverage.both, (unsigned long long)r->coverage.only_ref,
            (unsigned long long)r->coverage.only_test, (unsigned long long)r->coverage.neither);
    html_number(f, r->coverage_mae, "%.3g");
    fputs("</td></tr>\n</table>\n", f);

    fputs("<h2>Thresholds</h2>\n<table>\n<tr><th>check</th><th>limit</th><th>result</th></tr>\n", f);
    fprintf(f, "<tr><td>coverage agreement</td><td>&ge; %.3g %%</td><td>%s</td></tr>\n", 100 * t->min_coverage_agreement,
            r->pass_coverage ? "pass" : "fail");
    fprintf(f, "<tr><td>MAE, all pixels</td><td>&le; %.3g</td><td>%s</td></tr>\n", t->max_mae, r->pass_mae ? "pass" : "fail");
    fprintf(f, "<tr><td>pixels with an error over %.3g</td><td>&le; %.3g %%</td><td>%s</td></tr>\n", t->over_error,
            100 * t->max_over_fraction, r->pass_over ? "pass" : "fail");
    fprintf(f, "<tr><td>MAE per class covering &ge; %.3g %% of the picture</td><td>&le; %.3g</td><td>%s</td></tr>\n",
            100 * t->min_class_share, t->max_class_mae, r->pass_classes ? "pass" : "fail");
    fputs("</table>\n<p>The reasons for each limit are in docs/crosscheck.md.</p>\n", f);

    fputs("<h2>Timing</h2>\n<table>\n<tr><th>stage</th><th>time</th></tr>\n", f);
    html_seconds(f, "sylva: BVH build", r->sylva_bvh_seconds);
    html_seconds(f, "sylva: render (verification mode)", r->sylva_render_seconds);
    html_seconds(f, "sylva: POV-Ray export", o->pov_scene ? -1.0 : r->export_seconds);
    html_seconds(f, "POV-Ray: parse", r->povray.parse_seconds);
    html_seconds(f, "POV-Ray: bounding", r->povray.bounding_seconds);
    html_seconds(f, "POV-Ray: trace", r->povray.trace_seconds);
    html_seconds(f, "POV-Ray: whole process", r->povray.wall_seconds);
    double ratio = time_ratio(r);
    fputs("<tr><td>POV-Ray (parse + trace) / sylva (BVH + render)</td><td>", f);
    if (ratio >= 0) fprintf(f, "%.2f", ratio);
    else fputs("&ndash;", f);
    fputs("</td></tr>\n</table>\n<h2>Files</h2>\n<p><a href=\"sylva.exr\">sylva.exr</a> &middot; <code>", f);
    html_text(f, r->pov_image);
    fputs("</code> &middot; <code>", f);
    html_text(f, r->pov_log);
    fputs("</code> &middot; <a href=\"metrics.json\">metrics.json</a></p>\n</body>\n</html>\n", f);
    return atomic_file_commit(&out, err);
}

int crosscheck_write_report(const char *out_dir, const crosscheck_result *r, const crosscheck_options *o,
                            double heatmap_scale, err_buf *err)
{
    if (write_json(out_dir, r, o, err)) return -1;
    return write_html(out_dir, r, o, heatmap_scale, err);
}
