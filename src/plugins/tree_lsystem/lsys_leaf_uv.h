/* lsys_leaf_uv.h — texture coordinates of a leaf polygon in its own frame, so that a leaf
 * texture (stalk at (0.5, 0), tip at (0.5, 1), leaf_affine.h) lies on the outline the grammar
 * drew without changing it.
 *
 * The frame: the stalk is the polygon's first vertex; the long axis runs from it to the vertex
 * farthest from it (the tip), made square to the polygon's normal; the cross axis is
 * long axis x normal. v is the position along the long axis scaled to [0, 1] over the polygon's
 * extent (0 at the stalk end, 1 at the tip end); u is the signed distance from the line through
 * the stalk, 0.5 on that line, scaled so that the widest side reaches 0 or 1. The texture's
 * midrib thus runs from the first vertex towards the tip. */
#ifndef LSYS_LEAF_UV_H
#define LSYS_LEAF_UV_H

#include <stdint.h>

/* Writes 2 * n floats (u v per vertex) for the n >= 3 points xyz (x y z each) with the unit
 * normal `normal`. A polygon with no usable long axis (all points on one spot, or non-finite
 * coordinates) gets (0.5, 0.5) at every vertex. */
void lsys_leaf_uv(const double *xyz, uint32_t n, const double normal[3], float *uv);

#endif
