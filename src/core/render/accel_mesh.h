/* accel_mesh.h — a mesh in Embree: its opaque and its cut-out triangles (geometry/cutout.h) as two
 * triangle geometries at consecutive ids, the cut-out one with intersection and occlusion
 * filters that discard hits where the texture's alpha is below one half; a BVH of one mesh for
 * instances to share, and an instance of it in the top scene. */
#ifndef SYLVA_ACCEL_MESH_H
#define SYLVA_ACCEL_MESH_H

#include <embree3/rtcore.h>

#include "render/accel_types.h"
#include "util/err.h"

/* Adds one part of m (its opaque or its cut-out triangles) to rs as geometry `id` with Embree
 * mask `mask`, described in *g. Attaches nothing when the part has no triangles. Returns 0 or -1
 * with err. */
int accel_add_part(accel *a, RTCScene rs, const mesh *m, accel_part part, geom_kind kind, unsigned id,
                   unsigned mask, geom_info *g, err_buf *err);
/* Both parts of m at ids first (opaque) and first + 1 (cut-out), into g[0] and g[1]. */
int accel_add_mesh(accel *a, RTCScene rs, const mesh *m, geom_kind kind, unsigned first, unsigned mask,
                   geom_info g[ACCEL_PARTS], err_buf *err);
/* One BVH holding mesh m (its two parts in g[0] and g[1]), for instances to share; *out is
 * released by the caller. Returns 0 or -1 with err. */
int accel_build_shared(accel *a, const mesh *m, geom_kind kind, RTCScene *out, geom_info g[ACCEL_PARTS],
                       err_buf *err);
/* An instance of the shared BVH sc at top-level id of a, placed by xf, with Embree mask `mask`. */
int accel_add_instance(accel *a, RTCScene sc, const xform3x4 *xf, unsigned id, unsigned mask, err_buf *err);

#endif
