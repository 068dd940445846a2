/* sheet_content.h — what one sheet holds (sheet.h): the scene and the scene file it describes,
 * the facts of its viewpoint, its two pictures and the wireline's paths, the render's samples,
 * the study's other frames and the page. Nothing is owned: every field is the caller's. */
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
} sheet;

#endif
