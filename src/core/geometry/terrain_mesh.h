/* terrain_mesh.h — the terrain heightfield tessellated as every back end draws it: one vertex
 * per node at (x0 + i dx, y0 + j dy, z), two triangles per cell split along the diagonal from
 * node (i, j) to (i+1, j+1), vertex normals from central differences of the heights (one-sided
 * at the border), uv from 0 to 1 across the grid, and each cell's material from its first node.
 */
#ifndef SYLVA_TERRAIN_MESH_H
#define SYLVA_TERRAIN_MESH_H

#include "scene/mesh.h"
#include "sylva/plugin.h"
#include "util/err.h"

/* A (nx - 1) x (ny - 1) x 2 triangle mesh of hf (nx, ny >= 2). Cell (i, j) holds triangles
 * 2 (j (nx - 1) + i) and the one after it, with material hf->material at node (i, j), or
 * `fallback` where the heightfield has no material there (none, or -1). Returns a new mesh
 * (caller frees with mesh_free), or NULL with err set (out of memory). */
mesh *terrain_mesh_build(const sylva_heightfield *hf, int32_t fallback, err_buf *err);

#endif
