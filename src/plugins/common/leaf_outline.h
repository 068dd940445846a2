/* leaf_outline.h — an affine-map leaf (leaf_affine.h) as geometry: the outline of its mask
 * traced along the texel edges, simplified to a polygon within a tolerance and cut into
 * triangles, for a plugin that draws a leaf as triangles rather than as an alpha-masked card.
 *
 * Coordinates are the leaf's unit square (x right, y up, stalk at y = 0), as the maps'. The
 * polygon is the outer boundary of the largest piece of the mask, counter-clockwise; the
 * triangles index its vertices, each counter-clockwise, and together cover it exactly.
 *
 * Ownership: a leaf_outline owns its vertex and triangle arrays; leaf_outline_free releases
 * them (and accepts NULL). Includes only the C library. */
#ifndef SYLVA_LEAF_OUTLINE_H
#define SYLVA_LEAF_OUTLINE_H

#include <stdint.h>

/* Polygons are simplified to at most this many vertices (the tolerance is raised until so). */
#define LEAF_OUTLINE_MAX_VERTICES 256u

typedef struct leaf_outline {
    uint32_t n;          /* polygon vertices */
    double (*xy)[2];     /* n points, counter-clockwise; owned */
    uint32_t nt;         /* triangles: n - 2 */
    uint32_t (*tri)[3];  /* nt triangles of vertex indices, counter-clockwise; owned */
} leaf_outline;

/* Traces the outline of inside (size * size bytes, row 0 the top, non-zero inside, as
 * leaf_affine_outline fills it), simplifies it so that no texel corner of the traced boundary
 * lies farther than `tolerance` texels from the polygon (tolerance >= 0; 1 removes the
 * staircase of the texels), and triangulates it. Returns 0; 1 when the mask is empty or no
 * simple polygon of at most LEAF_OUTLINE_MAX_VERTICES is found (out is then empty); -1 when out
 * of memory. */
int leaf_outline_trace(const uint8_t *inside, uint32_t size, double tolerance, leaf_outline *out);

/* The polygon's area (the sum of its triangles' areas), in the unit square's units. */
double leaf_outline_area(const leaf_outline *o);

void leaf_outline_free(leaf_outline *o);

#endif
