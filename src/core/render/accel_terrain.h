/* accel_terrain.h — the terrain heightfield in Embree 3 as grid geometry (RTC_GEOMETRY_TYPE_GRID):
 * one float3 vertex per node of each of the terrain's grids (the heightfield and its levels of
 * detail, geometry/terrain_mesh.h) and tiles of at most ACCEL_TERRAIN_TILE cells a side over
 * that one vertex buffer, covering each grid's drawn cells (its window less the next finer
 * level's), with no index buffer, no normals and no uvs. Embree splits each grid quad along
 * the diagonal from its second to its fourth vertex; the vertex rows are stored from north to
 * south so that this is the diagonal from node (i, j) to (i+1, j+1), the one every back end draws
 * (geometry/terrain_mesh.h). A hit is turned back into that tessellation's triangle, and its
 * barycentrics are computed again in double precision from the ray and the triangle, so shading
 * sees the same triangles, normals, uvs and materials as from a triangle mesh.
 *
 * Memory per node: 12 bytes of vertices plus Embree's grid BVH, about 20 bytes at the peak of its
 * build (HEIGHTFIELD_RENDER_NODE_BYTES in scene/heightfield.h, measured by bench/terrain_big.c):
 * a 10,000 x 10,000 terrain takes about 3 GB here, where the same triangles as a triangle mesh
 * take about 19 GB.
 *
 * Ownership: an accel_terrain (the accel's) owns the vertex buffer and the tile table and is
 * freed by accel_terrain_free (accepts NULL); Embree owns its copy of the tiles.
 */
#ifndef SYLVA_ACCEL_TERRAIN_H
#define SYLVA_ACCEL_TERRAIN_H

#include <embree3/rtcore.h>

#include "render/accel_types.h"
#include "util/err.h"

#define ACCEL_TERRAIN_TILE 32766u /* cells along a tile's side: Embree's largest grid */

/* One tile: cells [i0, i0 + w) x [j0, j0 + h) of grid `grid`, whose nodes start at vertex
 * first_vertex. */
typedef struct accel_terrain_tile {
    uint32_t grid, i0, j0, w, h, first_vertex;
} accel_terrain_tile;

struct accel_terrain {
    float *vertices;             /* every grid's nodes, grid after grid, rows north to south */
    accel_terrain_tile *tiles;   /* Embree's primitive id is the index here */
    uint32_t n_tiles;
};

/* Attaches the scene's terrain to rs as geometry `id` (a cut-out filter on it when a terrain
 * material is a cut-out), into a->terrain. Returns 0 or -1 with err. */
int accel_terrain_add(accel *a, RTCScene rs, unsigned id, err_buf *err);
void accel_terrain_free(struct accel_terrain *t);

/* Shading data for a hit on the terrain geometry. */
void accel_terrain_shade(const accel *a, const struct RTCRayHit *rh, hit_info *h);

/* The procedural ground's albedo and shading normal (render/ground_shade.h) on terrain hit h
 * (the grid or its apron) of ray rh; nothing when the terrain keeps its materials. With
 * a->flat_ground, the colour of the POV-Ray export's ground image and no micro-relief, as the
 * export shows it (pov/pov_ground.h). */
void accel_terrain_ground(const accel *a, const struct RTCRayHit *rh, hit_info *h);

#endif
