/* sheet_map.h — a sheet's location map: the surveyed terrain as a hillshade around a viewpoint
 * and the development, with the viewpoint numbered, its frame's field of view as a wedge along its
 * heading (a photograph's camera, number 0, marked P), the development's structures marked and named, a north arrow and a scale bar. The map
 * is square metres to square millimetres, north up; it spans the viewpoint and every development
 * structure with a margin of a fifth, and at least MAP_MIN_SPAN metres. */
#ifndef SYLVA_SHEET_MAP_H
#define SYLVA_SHEET_MAP_H

#include <cairo.h>

#include "scene/scene.h"
#include "scene_file/scene_file.h"
#include "sheet/sheet_view.h"
#include "util/err.h"

#define MAP_MIN_SPAN 500.0

/* Draws the map of v (its eye at eye, local metres) into the rectangle (x, y, w, h) millimetres of
 * cr at dpi. Returns 0, or -1 with err set (out of memory). */
int sheet_map_draw(cairo_t *cr, const scene *s, const scene_file *sf, const sheet_view *v, const double eye[2],
                   double x, double y, double w, double h, double dpi, err_buf *err);

#endif
