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
 * accel_shade() turns an Embree hit into world-space shading data. Embree's hit.Ng is in
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

#include "geometry/cutout.h"
#include "scene/scene.h"
#include "util/err.h"
#include "util/vec3.h"

/* Geometry ids. A mesh's two parts sit at consecutive ids, opaque first:
 *   in a prototype's scene:  ACCEL_PART_OPAQUE (0) and ACCEL_PART_CUTOUT (1);
 *   in the top scene:        the terrain at ACCEL_TOP_TERRAIN (0), the apron beyond its edge
 *                            (geometry/terrain_apron.h) at ACCEL_TOP_APRON (1), the water at
 *                            ACCEL_TOP_WATER (2, opaque only), object o at
 *                            ACCEL_TOP_FIRST_OBJECT + 2 o + part (3 + 2 o, 4 + 2 o), or, when
 *                            it places a model, the instance of the model's BVH at 3 + 2 o
 *                            (whose own geometries are parts 0 and 1), and plant instance i
 *                            at first_instance + i, after the last object. */
typedef enum accel_part { ACCEL_PART_OPAQUE = 0, ACCEL_PART_CUTOUT = 1, ACCEL_PARTS = 2 } accel_part;
enum { ACCEL_TOP_TERRAIN = 0, ACCEL_TOP_APRON = 1, ACCEL_TOP_WATER = 2, ACCEL_TOP_FIRST_OBJECT = 3 };

static inline unsigned accel_top_object_id(uint32_t o, accel_part part)
{
    return ACCEL_TOP_FIRST_OBJECT + ACCEL_PARTS * o + part;
}

/* What each top-level geometry is, as Embree geometry masks: a ray meets only the geometries
 * whose mask shares a bit with its own. The renderer's rays carry every bit; a visibility map
 * (ztv/) screens with some of them. */
enum {
    ACCEL_MASK_GROUND = 1u,      /* the terrain, its apron and the water surfaces */
    ACCEL_MASK_PLANT = 2u,       /* the plant instances */
    ACCEL_MASK_OBJECT = 4u,      /* objects that are not part of a development */
    ACCEL_MASK_DEVELOPMENT = 8u, /* objects of a development, and its new planting */
    ACCEL_MASK_FAR_PLANT = 16u,  /* plants that camera rays see as crown proxies (crown_proxy.h) */
    ACCEL_MASK_PROXY = 32u       /* the crown proxies: met by camera rays alone */
};

typedef enum geom_kind { GEOM_TERRAIN = 1, GEOM_WATER, GEOM_OBJECT, GEOM_PROTOTYPE } geom_kind;

typedef struct geom_info {
    geom_kind kind;
    const mesh *mesh;          /* shading source; NULL for the terrain (its heightfield is) */
    cutout_part part;          /* the mesh's triangles in this geometry (Embree's primIDs); owned */
    const scene *scene;        /* for materials and textures in the filter */
    const struct accel_terrain *terrain; /* the terrain's tiles (GEOM_TERRAIN only) */
    int alpha;                 /* 1: the cut-out part, filtered by texture alpha */
    float crossing;            /* crown proxies: transmittance of one crossing of the envelope for
                                * shadow rays (render/crown_proxy.h) */
    float opacity;             /* crown proxies: the chance that a camera ray meets the envelope */
} geom_info;

struct accel_errors;
struct accel_terrain;
struct crown_proxies;

typedef struct accel {
    RTCDevice device;
    RTCScene top;
    const scene *scene;
    RTCScene *proto_scenes;    /* n_prototypes; owned (released) */
    geom_info *proto_geoms;    /* ACCEL_PARTS per prototype, at p * ACCEL_PARTS + part; owned */
    RTCScene *model_scenes;    /* n_models; owned (released) */
    geom_info *model_geoms;    /* ACCEL_PARTS per model, at m * ACCEL_PARTS + part; owned */
    geom_info *top_geoms;      /* per top-level non-instance geometry id; owned */
    uint32_t n_top_geoms;
    uint32_t first_instance;   /* top geomID of instance 0 */
    struct accel_terrain *terrain; /* the terrain's grid geometry (accel_terrain.h); owned */
    mesh *water_mesh;          /* owned */
    mesh *apron_mesh;          /* the terrain beyond its edge, or NULL; owned */
    struct accel_errors *errors; /* what Embree's error callback recorded; owned */
    struct ground_texture *ground; /* the procedural ground (geometry/ground_texture.h), or NULL; owned */
    float pixel_angle;         /* radians a pixel spans: the ground texture's footprint (0: none) */
    int flat_ground;           /* 1: the ground as the POV-Ray export has it (verification mode) */
    struct crown_proxies *proxies; /* the distant plants' crown proxies (crown_proxy.h), or NULL; owned */
    uint32_t first_proxy;      /* top geomID of crown proxy 0 */
    float bounds_lo[3], bounds_hi[3]; /* of the whole scene */
    int bark_relief;           /* 1: accel_shade tilts bark's normals (bark_bump.h); 0 (as built):
                                * the mesh's normals, which the verification mode compares */
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
    uint32_t object_id;        /* object index + 1, 0 when not an object */
    geom_kind kind;
} hit_info;

/* Builds everything. threads: Embree's build threads (0: all). Returns 0 or -1 with err.
 * accel_build_open then accel_commit. */
int accel_build(accel *a, const scene *s, unsigned threads, err_buf *err);
/* Builds everything but the top scene's BVH, so that geometry can still be added to the top
 * scene or re-masked (the crown proxies) before its one build; accel_commit finishes. Returns 0
 * or -1 with err (a freed). */
int accel_build_open(accel *a, const scene *s, unsigned threads, err_buf *err);
/* Builds the top scene's BVH and reads the scene's bounds. Returns 0 or -1 with err (a freed). */
int accel_commit(accel *a, err_buf *err);
void accel_free(accel *a); /* accepts a zeroed accel */

/* The first error Embree reported on a's device since it was built, into err: returns -1 with
 * it, or 0 when there was none. Call it on the thread that owns err, after tracing. */
int accel_device_error(const accel *a, err_buf *err);

/* One BVH holding mesh m (its two parts in g[0] and g[1]), for instances to share; *out is
 * released by the caller. Returns 0 or -1 with err. */
int accel_build_shared(accel *a, const mesh *m, geom_kind kind, RTCScene *out, geom_info g[ACCEL_PARTS],
                       err_buf *err);
/* An instance of the shared BVH sc at top-level id of a, placed by xf, with Embree mask `mask`. */
int accel_add_instance(accel *a, RTCScene sc, const xform3x4 *xf, unsigned id, unsigned mask, err_buf *err);

/* The object a hit lies on: its index + 1, or 0 when it is not on an object. */
uint32_t accel_hit_object(const accel *a, const struct RTCRayHit *rh);

/* Shading data for a hit of ray (org, dir). */
void accel_shade(const accel *a, const struct RTCRayHit *rh, hit_info *h);

#endif
