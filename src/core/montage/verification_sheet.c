/* verification_sheet.c — the verification sheet as HTML and as a PNG. */
#include "montage/verification_sheet.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/atomic_file.h"
#include "io/raster_canvas.h"
#include "util/html_text.h"

#define FIELD_MAX 24
#define FIELD_TEXT 160
#define SHEET_WIDTH 1600u     /* the PNG's width, pixels */
#define SHEET_MARGIN 24
#define SHEET_SCALE 2         /* font pixels per canvas pixel */
#define SHEET_LINE (CANVAS_TEXT_HEIGHT * SHEET_SCALE + 8)
#define SHEET_ROWS_MAX 30     /* residual rows on the PNG (all of them on the HTML page) */

typedef struct field {
    const char *label;
    char value[FIELD_TEXT];
} field;

/* printf into a field, or a dash when the first number is not known. */
static void put(field *f, int *n, const char *label, double known, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
static void put(field *f, int *n, const char *label, double known, const char *fmt, ...)
{
    field *x = &f[(*n)++];
    x->label = label;
    if (isnan(known)) {
        snprintf(x->value, sizeof x->value, "-");
        return;
    }
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(x->value, sizeof x->value, fmt, ap);
    va_end(ap);
}

/* The sheet's facts, in the order both forms show them. */
static int fields_of(const verification_sheet *v, field *f)
{
    int n = 0;
    const char *crs = v->crs_name ? v->crs_name : "local metres";
    put(f, &n, "Photograph", 0, "%s", v->photo ? v->photo : "-");
    put(f, &n, "Camera", 0, "%s", v->camera_model ? v->camera_model : "-");
    put(f, &n, "Viewpoint", v->viewpoint[0], "E %.1f  N %.1f  (%s)", v->viewpoint[0], v->viewpoint[1], crs);
    put(f, &n, "Camera height", v->viewpoint[2], "%.1f m", v->viewpoint[2]);
    put(f, &n, "Eye above ground", v->eye_above_ground, "%.2f m", v->eye_above_ground);
    put(f, &n, "Heading, pitch, roll", v->heading_deg, "%.2f, %.2f, %.2f deg", v->heading_deg, v->pitch_deg,
        v->roll_deg);
    put(f, &n, "Projection", 0, "%s", v->cylindrical ? "cylindrical panorama" : "perspective");
    put(f, &n, "Field of view", v->hfov_deg, "%.2f deg across, %.2f deg down", v->hfov_deg, v->vfov_deg);
    put(f, &n, "Focal length", v->focal_mm, "%.2f mm", v->focal_mm);
    put(f, &n, "35 mm equivalent", v->focal35_mm, "%.1f mm", v->focal35_mm);
    put(f, &n, "Sensor width", v->sensor_width_mm, "%.2f mm", v->sensor_width_mm);
    put(f, &n, "Lens distortion", v->k1, "k1 %.5f, k2 %.5f", v->k1, v->k2);
    put(f, &n, "To the development", v->development_distance_m, "%.0f m, bearing %.1f deg",
        v->development_distance_m, v->development_bearing_deg);
    put(f, &n, "Date and time", 0, "%s", v->date_time ? v->date_time : "-");
    put(f, &n, "Sun", v->sun_azimuth_deg, "azimuth %.2f deg, elevation %.2f deg", v->sun_azimuth_deg,
        v->sun_elevation_deg);
    put(f, &n, "Control points", v->n_residuals ? 0 : NAN, "%u, RMSE %.2f px", v->n_residuals, v->rmse_px);
    return n;
}

/* The HTML into the stream of out (opened, not yet committed). */
static void write_html(const verification_sheet *v, const field *f, int n, FILE *h)
{
    fputs("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>", h);
    html_text(h, v->title);
    fputs("</title>\n<style>body{font-family:sans-serif;margin:2em}table{border-collapse:collapse}"
          "td,th{border:1px solid #bbb;padding:3px 8px;text-align:left}td.n{text-align:right}"
          "img{max-width:49%;margin-right:1%}</style></head><body>\n<h1>", h);
    html_text(h, v->title);
    fputs("</h1>\n<table>\n", h);
    for (int i = 0; i < n; i++) {
        fputs("<tr><th>", h);
        html_text(h, f[i].label);
        fputs("</th><td>", h);
        html_text(h, f[i].value);
        fputs("</td></tr>\n", h);
    }
    fputs("</table>\n<h2>Wireline and photomontage</h2>\n<p>", h);
    if (v->wireline_file) {
        fputs("<img src=\"", h);
        html_text(h, v->wireline_file);
        fputs("\" alt=\"wireline\">", h);
    }
    if (v->montage_file) {
        fputs("<img src=\"", h);
        html_text(h, v->montage_file);
        fputs("\" alt=\"photomontage\">", h);
    }
    fputs("</p>\n", h);
    if (v->n_residuals) {
        fputs("<h2>Control points</h2>\n<table><tr><th>point</th><th>u (px)</th><th>v (px)</th>"
              "<th>du (px)</th><th>dv (px)</th><th>residual (px)</th></tr>\n", h);
        for (uint32_t i = 0; i < v->n_residuals; i++) {
            const sheet_residual *r = &v->residuals[i];
            fputs("<tr><td>", h);
            html_text(h, r->id);
            double c[5] = {r->u, r->v, r->du, r->dv, hypot(r->du, r->dv)};
            for (int k = 0; k < 5; k++) {
                fputs("</td><td class=\"n\">", h);
                html_number(h, c[k], k < 2 ? "%.1f" : "%.2f");
            }
            fputs("</td></tr>\n", h);
        }
        fputs("</table>\n", h);
    }
    fputs("</body></html>\n", h);
}

/* img scaled (box filter down, nearest up) into the canvas at (x0, y0), w x h pixels. */
static void blit(canvas *c, const sheet_image *img, int x0, int y0, int w, int h)
{
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            uint32_t sx0 = (uint32_t)((double)x / w * img->width), sy0 = (uint32_t)((double)y / h * img->height);
            uint32_t sx1 = (uint32_t)((double)(x + 1) / w * img->width), sy1 = (uint32_t)((double)(y + 1) / h * img->height);
            if (sx1 <= sx0) sx1 = sx0 + 1;
            if (sy1 <= sy0) sy1 = sy0 + 1;
            double sum[3] = {0, 0, 0};
            uint32_t k = 0;
            for (uint32_t sy = sy0; sy < sy1 && sy < img->height; sy++)
                for (uint32_t sx = sx0; sx < sx1 && sx < img->width; sx++, k++)
                    for (int ch = 0; ch < 3; ch++) sum[ch] += img->rgb[3 * ((size_t)sy * img->width + sx) + ch];
            uint8_t p[3];
            for (int ch = 0; ch < 3; ch++) p[ch] = (uint8_t)(k ? sum[ch] / k + 0.5 : 0);
            canvas_pixel(c, x0 + x, y0 + y, p);
        }
}

/* The PNG into out (opened, not yet committed). */
static int write_png(const verification_sheet *v, const field *f, int n, atomic_file *out, err_buf *err)
{
    const uint8_t white[3] = {255, 255, 255}, ink[3] = {20, 20, 20}, grey[3] = {90, 90, 90};
    int half = (int)(SHEET_WIDTH - 3 * SHEET_MARGIN) / 2;
    /* both images at the same height, each fitted into half the width */
    double aspect = 0;
    const sheet_image *imgs[2] = {&v->wireline, &v->montage};
    for (int i = 0; i < 2; i++)
        if (imgs[i]->rgb && imgs[i]->width) aspect = fmax(aspect, (double)imgs[i]->height / imgs[i]->width);
    int img_h = aspect > 0 ? (int)ceil(half * aspect) : 0;
    int rows = v->n_residuals < SHEET_ROWS_MAX ? (int)v->n_residuals : SHEET_ROWS_MAX;
    int fields_h = ((n + 1) / 2) * SHEET_LINE;
    int height = SHEET_MARGIN * 4 + 2 * SHEET_LINE + fields_h + img_h + SHEET_LINE +
                 (v->n_residuals ? (rows + 2) * SHEET_LINE : 0);
    canvas c;
    if (canvas_init(&c, SHEET_WIDTH, (uint32_t)height, white, err)) return -1;
    int y = SHEET_MARGIN;
    canvas_text(&c, SHEET_MARGIN, y, v->title ? v->title : "Photomontage", 3, ink);
    y += 2 * SHEET_LINE;
    for (int i = 0; i < n; i++) {
        int col = i % 2, x = SHEET_MARGIN + col * (half + SHEET_MARGIN);
        char line[FIELD_TEXT + 64];
        snprintf(line, sizeof line, "%s: %s", f[i].label, f[i].value);
        canvas_text(&c, x, y + (i / 2) * SHEET_LINE, line, SHEET_SCALE, ink);
    }
    y += fields_h + SHEET_MARGIN;
    for (int i = 0; i < 2; i++) {
        int x = SHEET_MARGIN + i * (half + SHEET_MARGIN);
        canvas_text(&c, x, y, i ? "PHOTOMONTAGE" : "WIRELINE", SHEET_SCALE, grey);
        if (imgs[i]->rgb && imgs[i]->width)
            blit(&c, imgs[i], x, y + SHEET_LINE, half, (int)ceil(half * (double)imgs[i]->height / imgs[i]->width));
    }
    y += SHEET_LINE + img_h + SHEET_MARGIN;
    if (v->n_residuals) {
        canvas_text(&c, SHEET_MARGIN, y, "POINT        U (PX)    V (PX)   DU (PX)   DV (PX)", SHEET_SCALE, grey);
        for (int i = 0; i < rows; i++) {
            const sheet_residual *r = &v->residuals[i];
            char line[160];
            snprintf(line, sizeof line, "%-10.10s %9.1f %9.1f %9.2f %9.2f", r->id ? r->id : "", r->u, r->v, r->du,
                     r->dv);
            canvas_text(&c, SHEET_MARGIN, y + (i + 1) * SHEET_LINE, line, SHEET_SCALE, ink);
        }
        if ((uint32_t)rows < v->n_residuals) {
            char more[64];
            snprintf(more, sizeof more, "... and %u more (the HTML sheet lists them all)", v->n_residuals - rows);
            canvas_text(&c, SHEET_MARGIN, y + (rows + 1) * SHEET_LINE, more, SHEET_SCALE, grey);
        }
    }
    int rc = canvas_write_png_into(&c, out, err);
    canvas_free(&c);
    return rc;
}

int verification_sheet_write(const verification_sheet *v, const char *html_path, const char *png_path, err_buf *err)
{
    field f[FIELD_MAX];
    int n = fields_of(v, f);
    atomic_file html = {.fd = -1, .slot = -1}, png = {.fd = -1, .slot = -1};
    FILE *h = NULL;
    int rc = 0;
    if (html_path && !(h = atomic_file_open_stream(&html, html_path, err))) rc = -1;
    if (!rc && h) write_html(v, f, n, h);
    if (!rc && png_path) rc = !atomic_file_open_stream(&png, png_path, err) || write_png(v, f, n, &png, err) ? -1 : 0;
    /* both written: only now does either take its place */
    if (!rc && h) rc = atomic_file_commit(&html, err);
    if (!rc && png_path) rc = atomic_file_commit(&png, err);
    if (rc) atomic_file_abort(&html), atomic_file_abort(&png);
    return rc;
}
