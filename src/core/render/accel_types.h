/* accel_types.h — the types of the scene in Embree (accel.h): the geometry ids and masks, what
 * each geometry is, the accel itself and the shading data of a hit. They stand apart from the
 * functions so that what accel.c builds from and shades with (accel_terrain.h, bark_bump.h,
 * crown_proxy.h, accel_mesh.h, accel_errors.h) sees them without including accel.h. */
#ifndef SYLVA_ACCEL_TYPES_H
#define SYLVA_ACCEL_TYPES_H

#include <embree3/rtcore.h>
#include <stdint.h>

#include "geometry/cutout.h"
#include "scene/scene.h"
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

struct accel_errors; /* accel_errors.h */
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
    uint32_t plants_held;      /* the plant instances in the top scene (accel_plants) */
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
    double frame[3];           /* the world position of the origin of the frame the Embree scene,
                                * its rays and accel_shade's points are in (accel_frame.h); 0 but
                                * in the verification render */
    mesh **framed_objects;     /* per object, its own mesh moved into the frame, or NULL where the
                                * object's mesh is used as it is; owned (NULL with a zero frame) */
} accel;

typedef struct hit_info {
    float t;
    vec3 p;                    /* position in the accel's frame: the world's but in the
                                  verification render (accel_frame.h) */
    vec3 ng;                   /* unit geometric normal, world */
    vec3 ns;                   /* unit shading normal, world */
    int one_normal;            /* 1: the triangle's three normals are one vector (POV-Ray then shades
                                  it by its geometric normal; the verification mode does alike) */
    float u, v;                /* texture coordinates */
    const material *mat;
    vec3 albedo;               /* material albedo times texture colour */
    uint32_t instance_id;      /* instance index + 1, 0 when not an instance */
    uint32_t species_id;       /* species index + 1, 0 when not a plant */
    uint32_t object_id;        /* object index + 1, 0 when not an object */
    geom_kind kind;
} hit_info;

#endif
