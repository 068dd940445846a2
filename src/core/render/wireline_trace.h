/* wireline_trace.h — the wireline (render/wireline.h) as vector paths, for a page to stroke: the
 * silhouette's outline traced by marching squares over its pixels' centres into closed
 * polylines, one round each part of the development in view (and one round a hole the
 * silhouette keeps), and the inner edges as polylines through the centres of their pixels (two
 * edge pixels side by side or one above the other linked, two diagonal ones only where no such
 * link joins them). Each polyline is simplified (Douglas–Peucker) to within
 * WIRELINE_TRACE_TOLERANCE pixels of the traced one, keeping the points where an outline comes
 * to or leaves the picture's edge. Everything is taken in the pixels' raster
 * order, so the same wireline gives the same paths.
 *
 * Coordinates are pixels from the picture's top-left corner, pixel (x, y) spanning [x, x + 1] x
 * [y, y + 1]. An outline where the development runs out of the picture runs along its edge (x = 0
 * or width, y = 0 or height); wireline_on_frame tells those stretches, which a drawing leaves out.
 *
 * Ownership: wireline_trace allocates p's arrays; wireline_paths_free releases them. */
#ifndef SYLVA_WIRELINE_TRACE_H
#define SYLVA_WIRELINE_TRACE_H

#include <stdint.h>

#include "render/wireline.h"
#include "util/err.h"

#define WIRELINE_TRACE_TOLERANCE 0.35 /* pixels a simplified polyline strays from the traced one */

typedef struct wireline_polyline {
    uint32_t first, n;       /* its points: points[first] to points[first + n - 1] */
    uint8_t kind;            /* WIRELINE_OUTLINE or WIRELINE_EDGE */
    uint8_t closed;          /* 1: the last point joins the first */
} wireline_polyline;

typedef struct wireline_paths {
    uint32_t width, height;  /* the picture's pixels */
    double (*points)[2];     /* n_points (x, y); owned */
    uint32_t n_points;
    wireline_polyline *lines; /* n_lines: the outlines first, then the inner edges; owned */
    uint32_t n_lines;
    uint32_t n_outlines;     /* closed outlines among lines */
} wireline_paths;

/* Traces w's outline, and its inner edges when inner_edges is 1, into p. Returns 0, or -1 with
 * err set (out of memory) and p empty. */
int wireline_trace(wireline_paths *p, const wireline *w, int inner_edges, err_buf *err);
void wireline_paths_free(wireline_paths *p); /* accepts a zeroed one */

/* 1 when the segment from a to b of an outline lies along the picture's edge. */
int wireline_on_frame(const wireline_paths *p, const double a[2], const double b[2]);

#endif
