/* montage_run.h — a photomontage from a scene and its photograph (`sylva montage`,
 * docs/photomontage.md): the photograph read with its EXIF, the camera matched to the control
 * points (or the scene's camera taken as it is), the scene rendered with and without the
 * development at the photograph's size through the matched camera (lens distortion included),
 * the development composited into the photograph in linear light with the terrain and trees as
 * holdouts and the shadow catcher on, and the files a reviewer needs written into a folder:
 * montage.png and .exr, mask.png, existing.png (the photograph as it is), wireline.png, the
 * verification sheet (sheet.pdf, sheet.png; montage/verification_sheet.h) and with control points
 * residuals.csv.
 *
 * The scene's camera is replaced by the matched one. A cylindrical panorama (the context views
 * photomontage guidance asks for) is rendered and composited through the scene's camera as it
 * is: the match solves perspective cameras only. Nothing else is kept.
 */
#ifndef SYLVA_MONTAGE_RUN_H
#define SYLVA_MONTAGE_RUN_H

#include <stdint.h>

#include "io/photo.h"
#include "montage/camera_match.h"
#include "scene/scene.h"
#include "util/err.h"

struct scene_file; /* scene_file/scene_file.h: the sections of the study read here */

typedef struct montage_options {
    const char *dir;           /* the output folder (must exist) */
    const char *photo;         /* the photograph, or NULL: the scene's photo: file */
    const char *points;        /* control points, or NULL: the scene's photo: control_points */
    uint32_t spp;              /* 0: the scene's */
    unsigned threads;          /* 0: one per core */
    double dpi;                /* the sheet's pixels per inch; 0: the study: section's (300) */
    int quiet;
} montage_options;

typedef struct montage_report {
    camera_model camera;       /* the camera rendered through */
    camera_match *match;       /* the match, or NULL without control points; owned (montage_report_free) */
    double sensor_width_mm;    /* 0: unknown */
    double render_seconds;
} montage_report;

/* The camera the match starts from (or the montage renders through, without control points):
 * the scene's, or with photo: camera_from_exif the photograph's GPS position, altitude and
 * direction on the site's map; at the photograph's size, with the focal length of photo: or
 * the EXIF when the sensor width (photo: or the EXIF's, into *sensor_mm, 0 when unknown) is
 * known. Returns 0, or -1 with err set (no GPS in the EXIF, a position PROJ cannot convert). */
int montage_start_camera(const scene *s, const struct scene_file *sf, const photo *ph, camera_model *m, double *sensor_mm,
                         err_buf *err);

/* Makes the photomontage of s (built from sf). Returns 0, or -1 with err set. */
int montage_run(scene *s, const struct scene_file *sf, const montage_options *o, montage_report *rep, err_buf *err);
void montage_report_free(montage_report *r); /* accepts a zeroed one */

#endif
