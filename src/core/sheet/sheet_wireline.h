/* sheet_wireline.h — the wireline on a sheet as vector strokes (docs/study.md, Sheets): the
 * development's outline and inner edges as render/wireline_trace.h traces them from the rendered
 * pixels, stroked in the page's millimetres over the existing view's picture, so the PDF holds
 * them as paths at any zoom and the PNG draws the same lines. */
#ifndef SYLVA_SHEET_WIRELINE_H
#define SYLVA_SHEET_WIRELINE_H

#include <cairo.h>

#include "render/wireline_trace.h"

#define SHEET_OUTLINE_MM 0.2  /* the outline's stroke, red */
#define SHEET_EDGE_MM 0.12    /* the inner edges' stroke, yellow */

/* Strokes p over the rectangle (x, y, w, h) millimetres that shows its picture: the inner edges,
 * then the outline over them, clipped to the rectangle; an outline's stretch along the picture's
 * edge (the development running out of the frame) is left out. */
void sheet_wireline_draw(cairo_t *cr, const wireline_paths *p, double x, double y, double w, double h);

#endif
