/* montage_run.c — the photomontage pipeline: plate, camera match, renders, composite, files. */
#include "montage/montage_run.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/image_io.h"
#include "io/photo.h"
#include "montage/composite.h"
#include "montage/control_points.h"
#include "montage/verification_sheet.h"
#include "render/camera.h"
#include "render/wireline.h"
#include "site/site_frame.h"
#include "scene_file/scene_file.h"
#include "sheet/sheet.h"
#include "util/progress.h"


/* With camera_from_exif: the camera at the photograph's GPS position (its altitude as the
 * height) turned to its GPS direction, on the site's map. The direction is taken as a bearing
 * from grid north (true and grid north differ by the meridian convergence, a degree or two,
 * which the match corrects). */
static int exif_camera(const scene_file *sf, const photo *ph, camera_model *m, err_buf *err)
{
    const photo_exif *x = &ph->exif;
    if (!x->has_gps_position)
        return err_set(err, "photo: camera_from_exif: the photograph's EXIF has no GPS position; give the camera's "
                            "position in camera: instead");
    site_frame *f = site_frame_new(sf->site.crs_wkt, NULL, err);
    double map[2];
    int rc = !f || site_frame_from_lonlat(f, x->longitude_deg, x->latitude_deg, map, err) ? -1 : 0;
    site_frame_free(f);
    if (rc) return -1;
    m->position[0] = map[0] - sf->site.origin[0], m->position[1] = map[1] - sf->site.origin[1];
    if (x->has_gps_altitude) m->position[2] = x->altitude_m - sf->site.origin[2];
    if (x->has_gps_direction) m->heading_deg = x->direction_deg, m->pitch_deg = 0, m->roll_deg = 0;
    return 0;
}

int montage_start_camera(const scene *s, const scene_file *sf, const photo *ph, camera_model *m, double *sensor,
                         err_buf *err)
{
    camera_model_from_settings(m, &s->camera, ph->width, ph->height);
    if (sf->photo.camera_from_exif && exif_camera(sf, ph, m, err)) return -1;
    *sensor = sf->photo.sensor_width_mm;
    if (*sensor <= 0 && photo_sensor_width(ph, sensor) == PHOTO_SENSOR_UNKNOWN) *sensor = 0;
    double focal = sf->photo.focal_length_mm > 0 ? sf->photo.focal_length_mm
                 : ph->exif.has_focal_length ? ph->exif.focal_length_mm : 0;
    if (focal > 0 && *sensor > 0) camera_model_set_focal_mm(m, focal, *sensor);
    return 0;
}

/* The camera matched to the points of cp, from cam (replaced by the solution). */
static int match_camera(const scene_file *sf, const control_points *cp, const char *path, camera_model *cam,
                        montage_report *rep, int quiet, err_buf *err)
{
    const double zero[3] = {0, 0, 0};
    const double *origin = zero;
    if (cp->map) {
        if (!sf->site.crs_wkt)
            return err_set(err, "%s: the control points are map coordinates, but the scene has no site: "
                                "section to place them; add one or give x,y,z local columns", path);
        origin = sf->site.origin;
    }
    unsigned free = CAMERA_FREE_ANGLES | (sf->photo.fit_focal_length ? CAMERA_FREE(CAMERA_FOCAL) : 0) |
                    (sf->photo.fit_position ? CAMERA_FREE_POSITION : 0) |
                    (sf->photo.fit_distortion ? CAMERA_FREE(CAMERA_K1) : 0);
    camera_match_aim(cam, cp->points, cp->n, origin);
    rep->match = camera_match_solve(cam, free, cp->points, cp->n, origin, err);
    if (!rep->match) {
        err_prefix(err, "%s: the camera cannot be matched: ", path);
        return -1;
    }
    *cam = rep->match->camera;
    if (!quiet) {
        fprintf(stderr, "montage: camera matched to %u points: RMSE %.2f px\n", cp->n, rep->match->rmse_px);
        for (int p = 0; p < CAMERA_PARAM_COUNT; p++)
            if (free & CAMERA_FREE(p))
                fprintf(stderr, "  %-14s %12.4f +- %.4f\n", camera_param_name((camera_param)p), rep->match->value[p],
                        rep->match->sigma[p]);
    }
    return 0;
}

/* The files of the montage into dir. */
static int write_files(const scene *s, const scene_file *sf, const photo *ph, const char *photo_path,
                       const control_points *cp, const montage_report *rep, const composite_renders *r,
                       const float *montage, const montage_options *o, err_buf *err)
{
    const char *dir = o->dir;
    uint32_t w = ph->width, h = ph->height;
    char path[4200];
    const float *alpha = r->full->development;
    uint8_t *plate8 = composite_srgb8(ph->rgb, (size_t)w * h), *mont8 = composite_srgb8(montage, (size_t)w * h);
    int rc = 0;
    if (!plate8 || !mont8) rc = err_nomem(err, "out of memory encoding the montage");
    snprintf(path, sizeof path, "%s/montage.png", dir);
    if (!rc) rc = composite_write_srgb(path, w, h, montage, err);
    snprintf(path, sizeof path, "%s/montage.exr", dir);
    if (!rc) rc = composite_write_exr(path, w, h, montage, alpha, err);
    snprintf(path, sizeof path, "%s/mask.png", dir);
    if (!rc) rc = composite_write_mask(path, w, h, alpha, err);
    snprintf(path, sizeof path, "%s/existing.png", dir);
    if (!rc) rc = image_write_u8(path, w, h, 3, plate8, err);
    /* the wireline over the photograph: outline red, inner edges yellow */
    camera cam;
    camera_init(&cam, &s->camera, w, h);
    wireline wl = {0};
    if (!rc) rc = wireline_find(&wl, r->full, s, &cam, err);
    if (!rc) { /* the sheet before the wireline is painted over the photograph */
        verification_inputs vi = {.s = s, .sf = sf, .ph = ph, .photo_path = photo_path, .cp = cp,
                                  .match = rep->match, .camera = &rep->camera, .sensor_width_mm = rep->sensor_width_mm,
                                  .spp = o->spp ? o->spp : s->image.spp,
                                  .page = sheet_page_size(sf->study.print_width_mm, o->dpi > 0 ? o->dpi : sf->study.dpi),
                                  .photograph = plate8, .montage = mont8, .wl = &wl};
        rc = verification_sheet_write(&vi, dir, err);
    }
    if (!rc) {
        const uint8_t red[3] = {255, 0, 0}, yellow[3] = {255, 220, 0};
        wireline_draw(&wl, plate8, red, yellow);
        snprintf(path, sizeof path, "%s/wireline.png", dir);
        rc = image_write_u8(path, w, h, 3, plate8, err);
    }
    wireline_free(&wl);
    free(plate8);
    free(mont8);
    /* a file that could not be written (a full disk) is an output failure, not a bad input */
    return rc ? err_default(err, ERR_OUTPUT) : 0;
}

/* The development's gain against the plate, known before anything is rendered: the photo:
 * section's exposure; without the section, 1 for a plate sylva rendered (its light is the
 * render's own), and for a photograph a refusal, as nothing says how its exposure matches. */
static int plate_gain(const scene_file *sf, const char *photo_path, const photo *ph, float *gain, err_buf *err)
{
    *gain = sf->photo.file ? (float)sf->photo.exposure : 1.0f;
    if (sf->photo.file || ph->sylva_render) return 0;
    return err_fail(err, ERR_USAGE,
                    "%s is a photograph and the scene has no photo: section, which gives the development's gain "
                    "against it; add photo: {file: %s, exposure: K} (K takes the render's linear radiance to the "
                    "photograph's linear values; 1 for a plate sylva rendered), with its control_points to match "
                    "the camera (docs/photomontage.md)", photo_path, photo_path);
}

int montage_run(scene *s, const scene_file *sf, const montage_options *o, montage_report *rep, err_buf *err)
{
    memset(rep, 0, sizeof *rep);
    const char *photo_path = o->photo ? o->photo : sf->photo.file;
    const char *points_path = o->points ? o->points : sf->photo.control_points;
    if (!photo_path)
        return err_fail(err, ERR_USAGE, "the scene has no photo: section; add one (photo: {file: view.jpg}) or "
                                        "give --photo");
    int panorama = s->camera.cylindrical;
    if (panorama && points_path)
        return err_fail(err, ERR_INPUT, "%s: the camera match solves a perspective camera, and the scene's camera "
                                        "is a cylindrical panorama; give the panorama's camera without control "
                                        "points, or match a single frame", points_path);
    photo ph = {0};
    control_points *cp = NULL;
    composite_renders r = {0};
    float *montage = NULL;
    float gain = 0;
    int rc = photo_read(photo_path, &ph, err);
    if (!rc) rc = plate_gain(sf, photo_path, &ph, &gain, err);
    camera_model cam;
    if (!rc && panorama) camera_model_from_settings(&cam, &s->camera, ph.width, ph.height); /* for the sheet */
    if (!rc && !panorama) rc = montage_start_camera(s, sf, &ph, &cam, &rep->sensor_width_mm, err);
    if (!rc && points_path && !(cp = control_points_read(points_path, NULL, err))) rc = -1;
    if (!rc && cp) rc = control_points_check_image(cp, points_path, photo_path, ph.width, ph.height, err);
    if (!rc && cp) rc = match_camera(sf, cp, points_path, &cam, rep, o->quiet, err);
    if (!rc) {
        rep->camera = cam;
        if (!panorama) { /* a panorama is rendered through the scene's camera as it is */
            camera_model_to_settings(&cam, &s->camera);
            s->camera.k1 = cam.k1, s->camera.k2 = cam.k2;
        }
        render_options ro = {.threads = o->threads, .quiet = o->quiet, .spp = o->spp, .width = ph.width,
                             .height = ph.height};
        double t0 = progress_now();
        rc = composite_render(s, &ro, &r, err);
        rep->render_seconds = progress_now() - t0;
    }
    if (!rc && !(montage = malloc((size_t)ph.width * ph.height * 3 * sizeof *montage)))
        rc = err_nomem(err, "out of memory for the montage");
    if (!rc) {
        composite_layers l = composite_layers_of(&r);
        image_f32 plate = {.width = ph.width, .height = ph.height, .channels = 3, .pixels = ph.rgb};
        rc = composite_apply(&l, &plate, gain, 1, montage, NULL, err);
    }
    if (!rc) rc = write_files(s, sf, &ph, photo_path, cp, rep, &r, montage, o, err);
    free(montage);
    composite_renders_free(&r);
    control_points_free(cp);
    photo_free(&ph);
    if (rc) montage_report_free(rep);
    return rc;
}

void montage_report_free(montage_report *r)
{
    camera_match_free(r->match);
    memset(r, 0, sizeof *r);
}
