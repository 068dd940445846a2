/* accel.h — the scene in Embree 3: one BVH (RTCScene) per prototype and per shared object
 * model, every plant instance and every object that places a model a single-level instance of
 * that BVH in the top scene, the water surface and the other objects (their own meshes) as
 * plain meshes in the top scene, as the scene geometry builds them (geometry/water_surface.h),
 * and the terrain as grid geometry over its heightfield (render/accel_terrain.h). Each mesh
 * enters as two geometries, its
 * opaque triangles and its cut-out triangles (geometry/cutout.h); the cut-out ones carry
 * intersection and occlusion filters that discard hits where the texture's alpha is below one
 * half.
 *
 * accel_shade() turns an Embree hit into shading data (world directions; points in the frame
 * the scene was built in, accel_frame.h). Embree's hit.Ng is in
 * instance space, so normals are computed here from the mesh and transformed by the instance's
 * inverse transpose.
 *
 * Embree reports errors through a callback on whichever thread meets them (its build workers
 * included); an accel records the first one and reports it on the calling thread: from
 * accel_build, and from accel_device_error after tracing.
 *
 * Ownership: an accel borrows the scene (which must outlive it) and owns the Embree device and
 * scenes, the terrain's vertices and the water mesh it builds, the triangle parts and the error record.
 */
#ifndef SYLVA_ACCEL_H
#define SYLVA_ACCEL_H

#include <embree3/rtcore.h>

#include "render/accel_errors.h" /* accel_device_error */
#include "render/accel_mesh.h"   /* shared BVHs and their instances */
#include "render/accel_types.h"  /* ids, masks, accel, hit_info */
#include "util/err.h"

/* Builds everything in the world's frame. threads: Embree's build threads (0: all). Returns 0 or
 * -1 with err. accel_build_open then accel_commit. */
int accel_build(accel *a, const scene *s, unsigned threads, err_buf *err);

/* Which plants a build holds: every one; none; or those whose horizontal bounds (their
 * prototype's box placed by the instance) reach the rectangle lo .. hi of the world, in metres.
 * A ray that stays over the rectangle meets the same plants in a BVH built WITHIN it as in one
 * built with ALL. */
typedef enum { ACCEL_PLANTS_ALL, ACCEL_PLANTS_NONE, ACCEL_PLANTS_WITHIN } accel_plants_kind;
typedef struct accel_plants {
    accel_plants_kind kind;
    double lo[2], hi[2];       /* ACCEL_PLANTS_WITHIN: the rectangle's south-west and north-east corners */
} accel_plants;

/* accel_build holding the plants `which` says (NULL: all), and the BVHs of the prototypes they
 * place alone. Returns 0 or -1 with err (a freed). */
int accel_build_plants(accel *a, const scene *s, unsigned threads, const accel_plants *which, err_buf *err);

/* Builds everything but the top scene's BVH, so that geometry can still be added to the top
 * scene or re-masked (the crown proxies, which need the world's frame) before its one build;
 * accel_commit finishes. frame: the world position of the frame's origin the scene is built in
 * (accel_frame.h), NULL for the world's. Returns 0 or -1 with err (a freed). */
int accel_build_open(accel *a, const scene *s, unsigned threads, const double frame[3], err_buf *err);
/* Builds the top scene's BVH and reads the scene's bounds. Returns 0 or -1 with err (a freed). */
int accel_commit(accel *a, err_buf *err);
void accel_free(accel *a); /* accepts a zeroed accel */

/* The object a hit lies on: its index + 1, or 0 when it is not on an object. */
uint32_t accel_hit_object(const accel *a, const struct RTCRayHit *rh);

/* Shading data for a hit of ray (org, dir), in a's frame. */
void accel_shade(const accel *a, const struct RTCRayHit *rh, hit_info *h);

#endif
