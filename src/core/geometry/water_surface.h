/* water_surface.h — the water over a terrain as every back end draws it: one horizontal
 * rectangle at the heightfield's water level over the extent of its nodes, as two triangles
 * (corners in the order south-west, south-east, north-east, north-west; uv 0 to 1 across it),
 * in the heightfield's water material, or the scene's when the heightfield names none.
 */
#ifndef SYLVA_WATER_SURFACE_H
#define SYLVA_WATER_SURFACE_H

#include "scene/scene.h"
#include "util/err.h"

/* The rectangle's south-west corner (lo) and north-east corner (hi), both at the water level. */
void water_surface_extent(const sylva_heightfield *hf, double lo[3], double hi[3]);

/* The water surface of s's terrain into *out: a new mesh (caller frees with mesh_free), or NULL
 * when the scene has no terrain or its terrain no water. Returns 0, or -1 with err set and *out
 * NULL (out of memory). */
int water_surface_build(const scene *s, mesh **out, err_buf *err);

#endif
