/* terrain_mesh.h — the terrain heightfield tessellated as every back end draws it. The terrain
 * is one or more grids: the heightfield itself and, when the terrain plugin made them, its
 * levels of detail (sylva_terrain_level), each drawn where no finer level covers it. In each
 * grid: one vertex per node, two triangles per cell split along the diagonal from node (i, j)
 * to (i+1, j+1), vertex normals from central differences of the grid's heights (one-sided at
 * its border), uv from 0 to 1 across the heightfield, and each cell's material from its first
 * node.
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

/* One grid of the terrain: grid 0 is the heightfield, grid k + 1 its level k. Node (i, j) sits
 * at (x0 + (i0 + i / refine) dx, y0 + (j0 + j / refine) dy) of the heightfield. Its cells in
 * [hole_i0, hole_i1) x [hole_j0, hole_j1) (grid cells) are the next finer level's and are not
 * drawn here (an empty range when there is none). Borrows the heightfield. */
typedef struct terrain_grid {
    const sylva_heightfield *hf;
    const float *z;
    const int32_t *material;  /* NULL: none */
    uint32_t nx, ny;          /* nodes */
    uint32_t i0, j0, refine;  /* window in heightfield nodes; nodes per heightfield cell */
    uint32_t hole_i0, hole_j0, hole_i1, hole_j1;
} terrain_grid;

/* The number of grids of hf (1 + its levels) and grid g of them. */
uint32_t terrain_grid_count(const sylva_heightfield *hf);
terrain_grid terrain_grid_of(const sylva_heightfield *hf, uint32_t g);

/* 1 when cell (i, j) of g is drawn (not under a finer level). */
static inline int terrain_cell_drawn(const terrain_grid *g, uint32_t i, uint32_t j)
{
    return !(i >= g->hole_i0 && i < g->hole_i1 && j >= g->hole_j0 && j < g->hole_j1);
}

/* Node (i, j)'s position, unit normal and uv (any of them may be NULL). */
void terrain_node_vertex(const terrain_grid *g, uint32_t i, uint32_t j, float pos[3], float nrm[3],
                         float uv[2]);

/* The triangle number in g of the lower (half 0: nodes (i, j), (i+1, j), (i+1, j+1)) or upper
 * (half 1: (i, j), (i+1, j+1), (i, j+1)) triangle of cell (i, j): 2 (j (nx - 1) + i) + half. */
static inline uint32_t terrain_triangle_of_cell(const terrain_grid *g, uint32_t i, uint32_t j, uint32_t half)
{
    return 2 * (j * (g->nx - 1) + i) + half;
}

/* The node numbers (j nx + i) in g of triangle t's three corners, in the order above. */
void terrain_triangle_nodes(const terrain_grid *g, uint32_t t, uint32_t k[3]);

/* Triangle t's material: g's material at its cell's first node, or `fallback` where there is
 * none (no material array, or -1). */
int32_t terrain_triangle_material(const terrain_grid *g, uint32_t t, int32_t fallback);

/* Every drawn triangle of every grid of hf as one mesh (grid by grid, in each the triangles of
 * its drawn cells in order). Returns a new mesh (caller frees with mesh_free), or NULL with err
 * set (out of memory, or more than 2^32 vertices). */
mesh *terrain_mesh_build(const sylva_heightfield *hf, int32_t fallback, err_buf *err);

#endif
