/* wireline.h — the development's wireline: its outline and its visible edges as a photomontage's
 * verification shows them, drawn over the photograph so the rendered development can be checked
 * against the view.
 *
 * The edges are found in the rendered frame's centre-ray layers (render/film.h). The outline is
 * the development's silhouette: the pixels that show a development object (or its new planting),
 * with gaps of up to 2 * WIRELINE_CLOSING pixels closed and every hole filled (but a hole that
 * shows something nearer than all of the development, a tree in front), so that a lattice
 * tower or another open structure is drawn as one closed contour round each part in view, not as
 * the edges of its members; a pixel of the silhouette is on the outline when a neighbour (left,
 * right, above, below) is outside it. A development pixel inside is on an inner edge when a
 * neighbour shows something else through the structure (a gap between members), another part
 * of the development, a face turned more than
 * WIRELINE_CREASE_DEG from its own, or a point off the pixel's own surface by more than
 * WIRELINE_DEPTH_STEP of its distance (a wing of a building in front of another: the points
 * are placed from the depth layer along the camera's rays). Only what the camera sees is drawn: a part hidden
 * behind the terrain or a tree has no pixels. A line is one pixel wide, on the development's
 * side of the edge, so it lies within a pixel of the edge's true position.
 *
 * The silhouette itself is kept beside the lines (w->inside), for render/wireline_trace.h to trace
 * its outline as vector paths.
 *
 * Ownership: wireline_find allocates w->edge and w->inside; wireline_free releases them.
 */
#ifndef SYLVA_WIRELINE_H
#define SYLVA_WIRELINE_H

#include <stdint.h>

#include "render/camera.h"
#include "render/film.h"
#include "scene/scene.h"
#include "util/err.h"

#define WIRELINE_CREASE_DEG 25.0  /* normals of neighbouring pixels farther apart are an edge */
#define WIRELINE_CLOSING 2        /* pixels: gaps of the development up to twice this are closed */
#define WIRELINE_DEPTH_STEP 0.02  /* a neighbour's point off the pixel's tangent plane by this share
                                   * of the pixel's distance is an edge */

typedef enum wireline_kind { WIRELINE_NONE = 0, WIRELINE_OUTLINE = 1, WIRELINE_EDGE = 2 } wireline_kind;

typedef struct wireline {
    uint32_t width, height;
    uint8_t *edge;           /* width * height wireline_kinds, row 0 at the top; owned */
    uint8_t *inside;         /* width * height: 1 inside the silhouette; owned */
    uint64_t outline, inner; /* pixels of each kind */
} wireline;

/* The wireline of the development objects of s in film f, rendered from s through camera c.
 * Returns 0, or -1 with err set (out of memory). */
int wireline_find(wireline *w, const film *f, const scene *s, const camera *c, err_buf *err);
void wireline_free(wireline *w); /* accepts a zeroed one */

/* Paints the wireline over rgb (8-bit, 3 per pixel, w->width x w->height): the outline in
 * outline_rgb, the inner edges in edge_rgb (NULL: the outline alone). */
void wireline_draw(const wireline *w, uint8_t *rgb, const uint8_t outline_rgb[3], const uint8_t edge_rgb[3]);

#endif
