/* sheet_table.c — the text of a sheet's table (sheet_table.h). */
#include "sheet/sheet_table.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#define DEG (M_PI / 180.0)

double sheet_viewing_distance(double width_mm, double hfov_deg, int cylindrical)
{
    return cylindrical ? width_mm / (hfov_deg * DEG) : 0.5 * width_mm / tan(0.5 * hfov_deg * DEG);
}

typedef struct table {
    sheet_row *rows;
    uint32_t n;
} table;

static void row(table *t, const char *label, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static void row(table *t, const char *label, const char *fmt, ...)
{
    if (t->n >= SHEET_ROWS_MAX) return;
    sheet_row *r = &t->rows[t->n++];
    snprintf(r->label, sizeof r->label, "%s", label);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(r->text, sizeof r->text, fmt, ap);
    va_end(ap);
}

static void place_rows(table *t, const sheet *sh)
{
    const sheet_view *v = &sh->view;
    if (sh->photo) {
        row(t, "Photograph", "%s", sh->photo->file);
        row(t, "Camera position", "%s", sh->photo->position);
    } else row(t, "Viewpoint", "%u  %s", v->number, v->name);
    if (v->crs_name) row(t, "Grid reference", "E %.1f  N %.1f  (%s)", v->easting, v->northing, v->crs_name);
    else row(t, "Grid reference", "x %.1f  y %.1f  (local metres: the scene has no site)", v->easting, v->northing);
    if (sh->photo) row(t, "Camera height", "%.1f m", sh->photo->camera_height);
    if (isfinite(v->ground_level)) row(t, "Ground level", "%.1f m", v->ground_level);
    else row(t, "Ground level", "off the surveyed terrain");
    if (isfinite(v->eye_height)) row(t, "Eye height", "%.2f m above ground", v->eye_height);
    else row(t, "Eye height", "not known: no surveyed ground under the eye");
    row(t, "View direction", "%.1f\u00b0 from grid north, pitch %.1f\u00b0 %s", v->heading_deg, fabs(v->pitch_deg),
        v->pitch_deg >= 0 ? "up" : "down");
    if (v->nearest)
        row(t, "Nearest development", "%s (%s): %.0f m at bearing %.1f\u00b0; %u structure%s", v->nearest,
            v->development ? v->development : "development", v->distance_m, v->bearing_deg, v->structures,
            v->structures == 1 ? "" : "s");
    else row(t, "Nearest development", "none marked in the scene");
}

int sheet_planting_text(const sheet *sh, char *out, size_t n)
{
    const scene *s = sh->s;
    out[0] = 0;
    if (!s->planting_shown) return 0;
    snprintf(out, n, "year %g after planting (%.0f), %s", s->planting_years, s->planting_year + floor(s->planting_years),
             sh->sf->season.text ? sh->sf->season.text : "summer");
    return 1;
}

/* The planting plan the view shows: its year since planting and season, or that it is not shown. */
static void planting_row(table *t, const sheet *sh)
{
    char text[160];
    if (sheet_planting_text(sh, text, sizeof text))
        row(t, "Mitigation planting", "the plan of %.0f at %s (day %u of the year)", sh->s->planting_year, text,
            sh->s->season_day);
    else if (sh->sf->planting.n_features)
        row(t, "Mitigation planting", "not shown: the site before the plan of %.0f", sh->sf->planting.year);
}

static void time_rows(table *t, const sheet *sh)
{
    const sheet_view *v = &sh->view;
    if (sh->photo) {
        if (sh->photo->taken) row(t, "Photograph taken", "%s (the EXIF)", sh->photo->taken);
        else row(t, "Photograph taken", "not in the EXIF (no DateTimeOriginal with OffsetTimeOriginal)");
        if (v->local_time[0]) row(t, "Sun placed for", "%s", v->local_time);
        else row(t, "Sun placed for", "no time: the scene places the sun by azimuth and elevation alone");
    } else if (v->local_time[0]) row(t, "Date and local time", "%s", v->local_time);
    else row(t, "Date and local time", "not given: the scene places the sun by azimuth and elevation alone");
    row(t, "Sun", "azimuth %.1f\u00b0, elevation %.1f\u00b0", v->sun_azimuth_deg, v->sun_elevation_deg);
}

/* A length in millimetres, or "unknown". */
static const char *mm_text(char *out, size_t n, double mm)
{
    if (isfinite(mm)) snprintf(out, n, "%.1f mm", mm);
    else snprintf(out, n, "unknown");
    return out;
}

/* A photomontage's camera: the photograph's EXIF beside what the match made of it. */
static void photo_lens_rows(table *t, const sheet *sh)
{
    const sheet_view *v = &sh->view;
    const sheet_photo *ph = sh->photo;
    char a[48], b[48];
    row(t, "Camera", "%s%s%s", ph->camera ? ph->camera : "not in the EXIF", ph->lens ? ", lens " : "",
        ph->lens ? ph->lens : "");
    if (v->cylindrical) {
        row(t, "Projection", "cylindrical panorama, the scene's camera as given");
        row(t, "Lens (focal length)", "none: a cylindrical projection %.1f\u00b0 across", v->hfov_deg);
    } else {
        row(t, "Projection", "planar, rectilinear; radial distortion k1 %.4f, k2 %.4f", ph->k1, ph->k2);
        row(t, "Lens (focal length)", "%s %s; EXIF %s", mm_text(a, sizeof a, v->focal_mm),
            ph->points ? "matched" : "as given", mm_text(b, sizeof b, ph->exif_focal_mm));
    }
    if (isfinite(v->sensor_mm)) row(t, "Sensor width", "%.2f mm (%s)", v->sensor_mm, ph->sensor_source);
    else row(t, "Sensor width", "unknown (give photo: sensor_width)");
    if (v->cylindrical) row(t, "35 mm equivalent", "none (cylindrical)");
    else
        row(t, "35 mm equivalent", "%.1f mm (the field of view across a 36 mm frame); EXIF %s", v->focal35_mm,
            mm_text(b, sizeof b, ph->exif_focal35_mm));
    row(t, "Horizontal field of view", "%.2f\u00b0", v->hfov_deg);
    row(t, "Vertical field of view", "%.2f\u00b0", v->vfov_deg);
    row(t, "Photograph, render", "%u \u00d7 %u pixels; the development rendered at %u samples a pixel", v->width,
        v->height, sh->spp);
    row(t, "Visualisation type", "Type %d (TGN 06/19): %s", ph->type, ph->type_reason);
}

static void lens_rows(table *t, const sheet *sh)
{
    if (sh->photo) {
        photo_lens_rows(t, sh);
        return;
    }
    const sheet_view *v = &sh->view;
    row(t, "Camera", "sylva %s path tracer; a rendered view, no photograph", SYLVA_VERSION);
    if (v->cylindrical) {
        row(t, "Projection", "cylindrical panorama (%s)", v->frame);
        row(t, "Lens (focal length)", "none: a cylindrical projection %.1f\u00b0 across", v->hfov_deg);
        row(t, "Sensor width", "none (cylindrical)");
        row(t, "35 mm equivalent", "none (cylindrical)");
    } else {
        row(t, "Projection", "planar, rectilinear (%s)", v->frame);
        row(t, "Lens (focal length)", "%.1f mm", v->focal_mm);
        row(t, "Sensor width", "%.1f mm", v->sensor_mm);
        row(t, "35 mm equivalent", "%.1f mm", v->focal35_mm);
    }
    row(t, "Horizontal field of view", "%.2f\u00b0", v->hfov_deg);
    row(t, "Vertical field of view", "%.2f\u00b0", v->vfov_deg);
    row(t, "Render", "%u \u00d7 %u pixels, %u samples a pixel", v->width, v->height, sh->spp);
    row(t, "Visualisation type", "Type 2 (TGN 06/19): a 3D model view and wireline, no photograph");
}

static void print_rows(table *t, const sheet *sh, const sheet_panels *p, double k)
{
    const sheet_view *v = &sh->view;
    const page_size *pg = &sh->page;
    int a3 = fabs(pg->width_mm - SHEET_A3_WIDTH) < 0.05 && fabs(pg->height_mm - SHEET_A3_HEIGHT) < 0.05;
    row(t, "Print size", "%s%.0f \u00d7 %.0f mm at %.0f dpi; print at 100%%, not fitted to the paper",
        a3 ? "A3 landscape, " : "", pg->width_mm, pg->height_mm, pg->dpi);
    row(t, sh->photo ? "Photomontage printed" : "Proposed view printed", "%.0f \u00d7 %.0f mm; view it from %.0f mm", p->main_mm * k, p->height_main_mm * k,
        sheet_viewing_distance(p->main_mm * k, v->hfov_deg, v->cylindrical));
    row(t, sh->photo ? "Photograph, wireline" : "Existing view, wireline", "%.0f \u00d7 %.0f mm each; view them from %.0f mm", p->side_mm * k,
        p->height_side_mm * k, sheet_viewing_distance(p->side_mm * k, v->hfov_deg, v->cylindrical));
}

static void fit_row(table *t, const sheet *sh)
{
    const sheet_view *v = &sh->view;
    if (!v->structures) return;
    char span[160];
    snprintf(span, sizeof span, "%.1f\u00b0 to %.1f\u00b0 across and %.1f\u00b0 to %.1f\u00b0 up from the view's centre",
             v->dev_left_deg, v->dev_right_deg, v->dev_low_deg, v->dev_high_deg);
    if (v->development_fits) {
        row(t, "Development in frame", "whole: %s", span);
        return;
    }
    row(t, "Development in frame",
        "NOT whole: it spans %s; the frame holds \u00b1%.1f\u00b0 \u00d7 \u00b1%.1f\u00b0. The view is the viewpoint's, "
        "pitched %.1f\u00b0 %s, not tilted further; %s%s", span, 0.5 * v->hfov_deg, 0.5 * v->vfov_deg,
        fabs(v->pitch_deg), v->pitch_deg >= 0 ? "up" : "down",
        sh->photo           ? "a wider photograph or a panorama would show more"
        : v->cylindrical    ? "the panorama is the study's widest frame"
        : sh->wider_frames ? "the study's other frames may show more: "
                           : "render the study's cylindrical_90 frame for a panorama",
        !v->cylindrical && sh->wider_frames ? sh->wider_frames : "");
}

static void check_rows(table *t, const sheet *sh)
{
    const scene *s = sh->s;
    if (s->earth.curvature)
        row(t, "Earth curvature", "on, refraction k = %.2f, radius %.0f km", s->earth.refraction, s->earth.radius / 1000);
    else row(t, "Earth curvature", "off (a flat Earth)");
    const sheet_photo *ph = sh->photo;
    if (!ph) row(t, "Camera match", "none: no photograph was matched, so there are no residuals");
    else if (!ph->points) row(t, "Camera match", "none: no control points, so there are no residuals");
    else
        row(t, "Camera match", "%u control points, RMSE %.2f px (%.3f\u00b0); largest residual %.2f px (%s)",
            ph->points, ph->rmse_px, ph->rmse_deg, ph->largest_px, ph->largest_id ? ph->largest_id : "unnamed");
    row(t, "POV-Ray cross-check", "not run");
}

uint32_t sheet_table(const sheet *sh, const sheet_panels *p, double scale, sheet_row rows[SHEET_ROWS_MAX])
{
    table t = {rows, 0};
    place_rows(&t, sh);
    time_rows(&t, sh);
    planting_row(&t, sh);
    lens_rows(&t, sh);
    print_rows(&t, sh, p, scale);
    fit_row(&t, sh);
    check_rows(&t, sh);
    return t.n;
}
