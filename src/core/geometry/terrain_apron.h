/* terrain_apron.h — the terrain beyond the heightfield's edge, so that a view toward the edge
 * shows ground up to the horizon instead of a void under it: each edge cell continued outward,
 * flat at the heights of its edge nodes, out to a reach far enough that the sky can show below
 * the horizon by less than a pixel, and the four corners filled flat at the corner nodes'
 * heights (docs/rendering.md, "Beyond the terrain's edge").
 *
 * Each edge cell's strip is the parallelogram of its two edge nodes and the same two moved
 * outward by the reach: planar, so one quad (two triangles) spans it whatever the reach. Its
 * inner vertices are the heightfield's own edge vertices (geometry/terrain_mesh.h), so terrain
 * and apron share their seam. The whole apron takes the material most of the edge cells have
 * (ground cover continued as one plain, not as stripes of each edge cell's cover to the
 * horizon); normals point straight up.
 * A heightfield asks for it with beyond_edge (sylva_heightfield, ABI 1.2).
 */
#ifndef SYLVA_TERRAIN_APRON_H
#define SYLVA_TERRAIN_APRON_H

#include "scene/mesh.h"
#include "sylva/plugin.h"
#include "util/err.h"

/* How far the apron reaches beyond the edge for an eye at `eye` (local metres): 10^4 times
 * the eye's height above the lowest edge node (at least 1 m), so the sky below the horizon of
 * a flat apron subtends under 0.006 degrees, and at least 10 times the heightfield's size;
 * at most 5e7 m. */
double terrain_apron_reach(const sylva_heightfield *hf, const double eye[3]);

/* The apron of hf (4 (nx + ny - 2) + 8 triangles) into *out as a new mesh (caller frees with
 * mesh_free), or NULL when hf asks for none (beyond_edge 0 or absent). Returns 0, or -1 with err
 * set (out of memory). */
int terrain_apron_build(const sylva_heightfield *hf, int32_t fallback, double reach, mesh **out,
                        err_buf *err);

/* The terrain's mesh (terrain_mesh_build, material `material`) with its apron for an eye at
 * `eye` appended: the ground the path tracer sees, for the exporters. A new mesh (caller frees
 * with mesh_free), or NULL with err set. */
mesh *terrain_mesh_with_apron(const sylva_heightfield *hf, int32_t material, const double eye[3], err_buf *err);

#endif
