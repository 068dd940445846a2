/* accel.h — the scene in Embree 3: one BVH (RTCScene) per prototype, every instance a
 * single-level instance of its prototype's BVH in the top scene, and the terrain (heightfield
 * as triangles), the water surface and the objects as plain meshes in the top scene. Materials
 * with an alpha mask sit in their own geometry with intersection and occlusion filters that
 * discard hits where the texture's alpha is below one half.
 *
 * accel_shade() turns an Embree hit into world-space shading data. Embree's hit.Ng is in
 * instance space, so normals are computed here from the mesh and transformed by the instance's
 * inverse transpose.
 *
 * Ownership: an accel borrows the scene (which must outlive it) and owns the Embree device and
 * scenes, the terrain and water meshes it tessellates, and the index buffers it makes.
 */
#ifndef SYLVA_ACCEL_H
#define SYLVA_ACCEL_H

#include <embree3/rtcore.h>

#include "scene/scene.h"
#include "util/err.h"
#include "util/vec3.h"

typedef enum geom_kind { GEOM_TERRAIN = 1, GEOM_WATER, GEOM_OBJECT, GEOM_PROTOTYPE } geom_kind;

typedef struct geom_info {
    geom_kind kind;
    const mesh *mesh;          /* shading source */
    uint32_t *prim_to_tri;     /* Embree primID → mesh triangle; owned */
    uint32_t *indices;         /* the geometry's index buffer; owned */
    const scene *scene;        /* for materials and textures in the filter */
    int alpha;                 /* 1: filtered by texture alpha */
} geom_info;

typedef struct accel {
    RTCDevice device;
    RTCScene top;
    const scene *scene;
    RTCScene *proto_scenes;    /* n_prototypes; owned (released) */
    geom_info *proto_geoms;    /* 2 per prototype: [0] opaque, [1] alpha-masked; owned */
    geom_info *top_geoms;      /* per top-level non-instance geometry id; owned */
    uint32_t n_top_geoms;
    uint32_t first_instance;   /* top geomID of instance 0 */
    mesh *terrain_mesh;        /* owned */
    mesh *water_mesh;          /* owned */
    float bounds_lo[3], bounds_hi[3]; /* of the whole scene */
} accel;

typedef struct hit_info {
    float t;
    vec3 p;                    /* world position */
    vec3 ng;                   /* unit geometric normal, world */
    vec3 ns;                   /* unit shading normal, world */
    float u, v;                /* texture coordinates */
    const material *mat;
    vec3 albedo;               /* material albedo times texture colour */
    uint32_t instance_id;      /* instance index + 1, 0 when not an instance */
    uint32_t species_id;       /* species index + 1, 0 when not a plant */
    geom_kind kind;
} hit_info;

/* Builds everything. threads: Embree's build threads (0: all). Returns 0 or -1 with err. */
int accel_build(accel *a, const scene *s, unsigned threads, err_buf *err);
void accel_free(accel *a); /* accepts a zeroed accel */

/* Shading data for a hit of ray (org, dir). */
void accel_shade(const accel *a, const struct RTCRayHit *rh, hit_info *h);

/* Tessellates a heightfield into a mesh (2 triangles per cell, per-node materials with
 * `fallback` where the node has none). Caller frees. */
mesh *terrain_mesh_build(const sylva_heightfield *hf, int32_t fallback, err_buf *err);

#endif
