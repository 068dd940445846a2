/* verification_sheet.c — the photomontage's sheet through the sheet layer, and its residuals
 * (verification_sheet.h). It fills sheet/sheet_content.h from the montage's run; the page, the
 * table and the wireline's strokes are the sheet layer's. */
#include "montage/verification_sheet.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/atomic_file.h"
#include "render/wireline_trace.h"
#include "sheet/sheet.h"

#define DEG (M_PI / 180.0)

int verification_type(const verification_inputs *in, char *buf, size_t n, const char **reason)
{
    const scene_file *sf = in->sf;
    const camera_match *m = in->match;
    *reason = buf;
    if (!m || !in->cp) {
        *reason = "photomontage; the camera is not matched to control points, so nothing verifies it";
        return 3;
    }
    if (sf->photo.camera_from_exif) {
        *reason = "photomontage; the camera's position is the photograph's GPS, not surveyed";
        return 3;
    }
    if (m->free & CAMERA_FREE_POSITION) {
        *reason = "photomontage; the match placed the camera (fit_position), so its position is not the surveyed one";
        return 3;
    }
    if (!in->cp->map) {
        *reason = "photomontage; the control points are local coordinates, not surveyed on the site's map";
        return 3;
    }
    double rmse_deg = atan(m->rmse_px / camera_model_focal_px(&m->camera)) / DEG;
    if (!(rmse_deg <= VERIFIED_RMSE_DEG)) {
        snprintf(buf, n, "photomontage; the match's RMSE, %.3f\u00b0 at the camera, is over the %.2f\u00b0 that "
                         "would verify the surveyed position", rmse_deg, VERIFIED_RMSE_DEG);
        return 3;
    }
    snprintf(buf, n, "photomontage, survey verifiable: the camera at its surveyed position, %u surveyed control points "
                     "matched within %.3f\u00b0 (at most %.2f\u00b0)", m->n_points, rmse_deg, VERIFIED_RMSE_DEG);
    return 4;
}

/* Where the sensor width came from. */
static const char *sensor_source(const verification_inputs *in)
{
    if (!(in->sensor_width_mm > 0)) return NULL;
    if (in->sf->photo.sensor_width_mm > 0) return "given in photo:";
    double w;
    photo_sensor_source src = photo_sensor_width(in->ph, &w);
    return src == PHOTO_SENSOR_FOCAL_PLANE ? "the EXIF's focal-plane resolution"
         : src == PHOTO_SENSOR_35MM        ? "the EXIF's 35 mm equivalent"
                                           : "given";
}

/* The match's residuals into ph: their number, RMSE and the largest. */
static void residuals_of(const verification_inputs *in, sheet_photo *ph)
{
    const camera_match *m = in->match;
    if (!m || !in->cp) return;
    ph->points = m->n_points, ph->rmse_px = m->rmse_px;
    ph->rmse_deg = atan(m->rmse_px / camera_model_focal_px(&m->camera)) / DEG;
    for (uint32_t i = 0; i < m->n_points && i < in->cp->n; i++) {
        double r = hypot(m->residual[i][0], m->residual[i][1]);
        if (r > ph->largest_px || !ph->largest_id) ph->largest_px = r, ph->largest_id = in->cp->points[i].id;
    }
}

static const char *position_of(const verification_inputs *in)
{
    const scene_file *sf = in->sf;
    int moved = in->match && (in->match->free & CAMERA_FREE_POSITION);
    if (sf->photo.camera_from_exif)
        return moved ? "from the photograph's GPS (EXIF), then placed by the camera match"
                     : "the photograph's GPS (EXIF), held by the camera match";
    if (moved) return "placed by the camera match, from the scene's camera: as its start";
    return in->match ? "surveyed: the scene's camera: position, held by the camera match"
                     : "the scene's camera: position, as given";
}

/* One CSV field: quoted when it holds a comma, a quote or a line break. */
static void csv_text(FILE *f, const char *t)
{
    if (!strpbrk(t, ",\"\r\n")) {
        fputs(t, f);
        return;
    }
    fputc('"', f);
    for (; *t; t++) {
        if (*t == '"') fputc('"', f);
        fputc(*t, f);
    }
    fputc('"', f);
}

/* Every control point's residual, in sylva's pixels (docs/photomontage.md, Control-point files). */
static int write_residuals(const verification_inputs *in, const char *dir, err_buf *err)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/residuals.csv", dir);
    atomic_file af = {.fd = -1, .slot = -1};
    FILE *f = atomic_file_open_stream(&af, path, err);
    if (!f) return -1;
    fputs("id,u,v,du,dv,residual\n", f);
    const camera_match *m = in->match;
    for (uint32_t i = 0; i < m->n_points && i < in->cp->n; i++) {
        const control_point *p = &in->cp->points[i];
        csv_text(f, p->id ? p->id : "");
        fprintf(f, ",%.2f,%.2f,%.3f,%.3f,%.3f\n", p->pixel[0], p->pixel[1], m->residual[i][0], m->residual[i][1],
                hypot(m->residual[i][0], m->residual[i][1]));
    }
    return atomic_file_commit(&af, err);
}

int verification_sheet_write(const verification_inputs *in, const char *dir, err_buf *err)
{
    const scene *s = in->s;
    const photo *ph = in->ph;
    const photo_exif *x = &ph->exif;
    char make[160] = "", iso[32], taken[64] = "", reason[256];
    if (x->has_make || x->has_model)
        snprintf(make, sizeof make, "%s%s%s", x->has_make ? x->make : "", x->has_make && x->has_model ? " " : "",
                 x->has_model ? x->model : "");
    if (!photo_exif_iso8601(x, iso)) sheet_local_time(iso, taken, sizeof taken);
    const char *slash = strrchr(in->photo_path, '/');
    sheet_photo sp = {.file = slash ? slash + 1 : in->photo_path, .camera = make[0] ? make : NULL,
                      .lens = x->has_lens_model && x->lens_model[0] ? x->lens_model : NULL,
                      .taken = taken[0] ? taken : NULL, .position = position_of(in),
                      .exif_focal_mm = x->has_focal_length ? x->focal_length_mm : NAN,
                      .exif_focal35_mm = x->has_focal_length_35mm ? x->focal_length_35mm : NAN,
                      .sensor_source = sensor_source(in), .k1 = in->camera->k1, .k2 = in->camera->k2,
                      .camera_height = in->camera->position[2] + s->site.origin[2]};
    residuals_of(in, &sp);
    sp.type = verification_type(in, reason, sizeof reason, &sp.type_reason);

    /* the facts of the view through the camera rendered with, its lens on the photograph's sensor */
    camera_settings cs = s->camera;
    uint32_t w = ph->width, h = ph->height;
    if (!cs.cylindrical && in->sensor_width_mm > 0)
        cs.sensor_width_mm = in->sensor_width_mm, cs.focal_length_mm = camera_model_focal_mm(in->camera, in->sensor_width_mm);
    else if (!cs.cylindrical) cs.sensor_width_mm = cs.focal_length_mm = 0;
    sheet sh = {.s = s, .sf = in->sf, .eye = {cs.position[0], cs.position[1]}, .spp = in->spp, .page = in->page,
                .photo = &sp};
    sheet_view_of(s, in->sf, NULL, &cs, cs.cylindrical ? "cylindrical panorama" : "single frame", w, h, &sh.view);
    sh.view.name = sp.file;
    if (!cs.cylindrical && !(in->sensor_width_mm > 0)) sh.view.sensor_mm = sh.view.focal_mm = NAN;

    wireline_paths paths = {0}; /* owned here */
    int rc = wireline_trace(&paths, in->wl, 1, err);
    if (!rc) {
        sh.existing = (page_picture){w, h, in->photograph};
        sh.proposed = (page_picture){w, h, in->montage};
        sh.wireline = &paths;
        char pdf[4200], png[4200];
        snprintf(pdf, sizeof pdf, "%s/sheet.pdf", dir);
        snprintf(png, sizeof png, "%s/sheet.png", dir);
        rc = sheet_write(&sh, pdf, png, err);
    }
    wireline_paths_free(&paths);
    if (!rc && sp.points) rc = write_residuals(in, dir, err);
    return rc;
}
