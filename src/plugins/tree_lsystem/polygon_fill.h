/* polygon_fill.h — triangulation of a planar polygon in 3-D, convex or concave, by ear clipping
 * in the plane of its Newell normal. A polygon whose outline crosses itself still gets n - 2
 * triangles: when no ear is left the rest becomes a fan. */
#ifndef POLYGON_FILL_H
#define POLYGON_FILL_H

#include <stdint.h>

/* Triangulates the n >= 3 points xyz (x y z each). Writes up to n - 2 index triples into tri
 * (3 * (n - 2) entries) and the unit normal into normal; `scratch` holds 3 * n doubles and
 * n + n uint32 of working space (see POLYGON_FILL_SCRATCH). Returns the triangle count: n - 2,
 * or 0 when the points span no area (then normal is zero). */
#define POLYGON_FILL_SCRATCH_DOUBLES(n) (2u * (n))
#define POLYGON_FILL_SCRATCH_INDICES(n) (n)
uint32_t polygon_fill(const double *xyz, uint32_t n, uint32_t *tri, double normal[3], double *scratch_xy,
                      uint32_t *scratch_idx);

#endif
