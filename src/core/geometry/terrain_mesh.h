/* terrain_mesh.h — the terrain heightfield tessellated as every back end draws it: one vertex
 * per node at (x0 + i dx, y0 + j dy, z), two triangles per cell split along the diagonal from
 * node (i, j) to (i+1, j+1), vertex normals from central differences of the heights (one-sided
 * at the border), uv from 0 to 1 across the grid, and each cell's material from its first node.
 *
 * The node and triangle functions give one vertex or one triangle of that tessellation without
 * building it, so that a back end can draw a terrain of a hundred million nodes from the
 * heightfield alone (the path tracer does: render/accel_terrain.h); terrain_mesh_build gives the
 * whole tessellation as a mesh (the POV-Ray export writes it).
 */
#ifndef SYLVA_TERRAIN_MESH_H
#define SYLVA_TERRAIN_MESH_H

#include "scene/mesh.h"
#include "sylva/plugin.h"
#include "util/err.h"

/* Node (i, j)'s position, unit normal and uv (any of them may be NULL). */
void terrain_node_vertex(const sylva_heightfield *hf, uint32_t i, uint32_t j, float pos[3],
                         float nrm[3], float uv[2]);

/* The triangle number of the lower (half 0: nodes (i, j), (i+1, j), (i+1, j+1)) or upper (half 1:
 * (i, j), (i+1, j+1), (i, j+1)) triangle of cell (i, j): 2 (j (nx - 1) + i) + half. */
static inline uint32_t terrain_triangle_of_cell(const sylva_heightfield *hf, uint32_t i, uint32_t j,
                                                uint32_t half)
{
    return 2 * (j * (hf->nx - 1) + i) + half;
}

/* The node numbers (j nx + i) of triangle t's three corners, in the order above. */
void terrain_triangle_nodes(const sylva_heightfield *hf, uint32_t t, uint32_t k[3]);

/* Triangle t's material: hf->material at its cell's first node, or `fallback` where the
 * heightfield has none there (no material array, or -1). */
int32_t terrain_triangle_material(const sylva_heightfield *hf, uint32_t t, int32_t fallback);

/* A (nx - 1) x (ny - 1) x 2 triangle mesh of hf (nx, ny >= 2), triangle t as above. Returns a
 * new mesh (caller frees with mesh_free), or NULL with err set (out of memory). */
mesh *terrain_mesh_build(const sylva_heightfield *hf, int32_t fallback, err_buf *err);

#endif
