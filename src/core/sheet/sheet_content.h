/* sheet_content.h — what one sheet holds (sheet.h): the scene and the scene file it describes,
 * the facts of its viewpoint, its two pictures and the wireline's paths, the render's samples,
 * the study's other frames and the page; for a photomontage (`sylva montage`), the photograph
 * and its camera match besides. Nothing is owned: every field is the caller's. */
#ifndef SYLVA_SHEET_CONTENT_H
#define SYLVA_SHEET_CONTENT_H

#include "page/page.h"
#include "page/page_image.h"
#include "render/wireline_trace.h"
#include "scene/scene.h"
#include "scene_file/scene_file.h"
#include "sheet/sheet_view.h"

#define SHEET_A3_WIDTH 420.0
#define SHEET_A3_HEIGHT 297.0

/* What a photomontage's sheet states that a rendered view's does not: the photograph, its EXIF,
 * how its camera was found and matched, and the visualisation Type that follows (TGN 06/19,
 * Table 2: 3, a photomontage; 4, one verifiable by survey). */
typedef struct sheet_photo {
    const char *file;             /* the photograph's file name */
    const char *camera, *lens;    /* the EXIF's make and model, lens model; NULL: not given */
    const char *taken;            /* the capture date and time with its zone; NULL: not in the EXIF */
    const char *position;         /* how the camera's position was found, a phrase */
    double camera_height;         /* the eye's map height, metres */
    double exif_focal_mm, exif_focal35_mm; /* NAN: not in the EXIF */
    const char *sensor_source;    /* where the sensor width came from; NULL: not known */
    double k1, k2;                /* the lens's radial distortion rendered with */
    uint32_t points;              /* control points the camera was matched to; 0: no match */
    double rmse_px, rmse_deg;     /* the match's RMSE, in pixels and as an angle at the camera */
    double largest_px;            /* the largest point's residual */
    const char *largest_id;       /* and its name */
    int type;                     /* 3 or 4 */
    const char *type_reason;      /* why that Type, a phrase */
} sheet_photo;

typedef struct sheet {
    const scene *s;
    const scene_file *sf;
    sheet_view view;
    double eye[2];                          /* the viewpoint, local metres */
    page_picture existing, proposed;        /* rgb NULL: not on the sheet */
    const wireline_paths *wireline;         /* stroked over the existing view; NULL: not on the sheet */
    uint32_t spp;                           /* samples per pixel rendered with */
    const char *wider_frames;               /* the study's other frames ("cylindrical_90"), or NULL */
    page_size page;
    const sheet_photo *photo;               /* a photomontage's sheet; NULL: a study's rendered view */
} sheet;

#endif
