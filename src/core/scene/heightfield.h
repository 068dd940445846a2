/* heightfield.h — the terrain heightfield as a surface: the height and unit normal at any point
 * by bilinear interpolation of the four nodes around it. The one place that interpolates a
 * sylva_heightfield: the plugin host's terrain queries, the scene build's plants on the ground,
 * the scene geometry and the ecology maps all ask here.
 *
 * Node (i, j) stands at (x0 + i dx, y0 + j dy) with height z[j nx + i]; a point on the
 * heightfield's last row or column belongs to the cell before it. Where levels of detail cover
 * a point (sylva_terrain_level), the finest of them answers. Nothing is allocated.
 */
#ifndef SYLVA_HEIGHTFIELD_H
#define SYLVA_HEIGHTFIELD_H

#include "sylva/plugin.h"

/* What one heightfield node costs the host from the plugin's hands to the first pixel: 4 bytes
 * of height and 4 of material id in the heightfield, and 32 in the renderer (a 12-byte grid
 * vertex and Embree's grid BVH at the peak of its build, render/accel_terrain.h). */
#define HEIGHTFIELD_NODE_BYTES 8u
#define HEIGHTFIELD_RENDER_NODE_BYTES 32u

/* A phrase for messages and summaries: "N x M nodes D m apart", and its finer levels of
 * detail when it has any. Writes at most n bytes into buf and returns buf. */
const char *heightfield_describe(const sylva_heightfield *h, char *buf, size_t n);

/* Frees a heightfield the host made, its arrays and its levels; accepts NULL. */
void heightfield_free(sylva_heightfield *h);

/* Level k of h as a heightfield of its own (x0, y0, dx, dy of its nodes; no levels). */
sylva_heightfield heightfield_level_view(const sylva_heightfield *h, uint32_t k);

/* Height at (x, y) into *z; returns 0, or -1 (z untouched) when (x, y) lies outside the
 * heightfield's nodes (or is not a number). */
int heightfield_height(const sylva_heightfield *h, double x, double y, double *z);

/* Height at (x, y) of the surface as it is drawn (geometry/terrain_mesh.h): two triangles per
 * cell, split along the diagonal from node (i, j) to (i + 1, j + 1). Where a cell is not planar
 * it differs from the bilinear height; a point placed above the rendered ground asks here.
 * Returns 0, or -1 (z untouched) outside the heightfield. */
int heightfield_surface_height(const sylva_heightfield *h, double x, double y, double *z);

/* Height at the point of the heightfield nearest to (x, y), for any finite (x, y). */
double heightfield_height_clamped(const sylva_heightfield *h, double x, double y);

/* Unit normal of the interpolated surface at (x, y) into n; returns 0, or -1 outside. */
int heightfield_normal(const sylva_heightfield *h, double x, double y, double n[3]);

#endif
