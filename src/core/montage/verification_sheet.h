/* verification_sheet.h — the photomontage's verification sheet (docs/photomontage.md,
 * Verification sheet): the study's sheet (sheet/sheet.h) with the photomontage as the proposed
 * view, the photograph as the existing view, the wireline traced from the render and stroked over
 * the photograph, the location map, and the table filled for a photograph: its EXIF, how the
 * camera's position was found, the matched lens, the capture time, the camera match's residuals
 * and the visualisation Type (TGN 06/19, Table 2) that follows from them. Written as sheet.pdf and
 * sheet.png, with every control point's residual in residuals.csv.
 *
 * The Type: 4 (survey verifiable) when the camera stands at the position the scene's camera:
 * gives (surveyed; neither the EXIF's GPS nor moved by the match), the control points are map
 * coordinates in the site's CRS, and the match puts them within VERIFIED_RMSE_DEG of their
 * pixels as seen from the camera; otherwise 3, with the reason. Nothing is kept: the caller owns
 * every input. */
#ifndef SYLVA_VERIFICATION_SHEET_H
#define SYLVA_VERIFICATION_SHEET_H

#include <stddef.h>
#include <stdint.h>

#include "io/photo.h"
#include "montage/camera_match.h"
#include "montage/control_points.h"
#include "page/page.h"
#include "render/wireline.h"
#include "scene/scene.h"
#include "scene_file/scene_file.h"
#include "util/err.h"

#define VERIFIED_RMSE_DEG 0.05 /* the match's RMSE, as an angle at the camera, that verifies it */

typedef struct verification_inputs {
    const scene *s;                 /* rendered through the camera below */
    const scene_file *sf;
    const photo *ph;
    const char *photo_path;
    const control_points *cp;       /* NULL: no match */
    const camera_match *match;      /* NULL: no match */
    const camera_model *camera;     /* the camera rendered through */
    double sensor_width_mm;         /* 0: unknown */
    uint32_t spp;                   /* samples per pixel of the render */
    page_size page;
    const uint8_t *photograph, *montage; /* 8-bit sRGB at the photograph's size */
    const wireline *wl;             /* the development's wireline in the render */
} verification_inputs;

/* The Type of the montage in: 3 or 4, and why into *reason (a static phrase or reason_buf). */
int verification_type(const verification_inputs *in, char *reason_buf, size_t n, const char **reason);

/* Writes DIR/sheet.pdf, DIR/sheet.png and, with a match, DIR/residuals.csv (id, u, v, du, dv,
 * residual in pixels). Returns 0, or -1 with err set. */
int verification_sheet_write(const verification_inputs *in, const char *dir, err_buf *err);

#endif
