/* scene.h — the scene graph a back end renders: terrain, species prototypes (meshes, several
 * age variants per species), instances of them, objects (each its own mesh, or an instance of
 * a shared model mesh), materials and textures, the camera, sun, sky and image settings.
 *
 * Ownership: a scene owns everything in it: meshes, the terrain heightfield, textures,
 * material names and the arrays. scene_free releases it all. Settings are copied from the
 * scene_file, so a scene outlives the file it came from. There is no global state: two scenes
 * in one process are independent.
 */
#ifndef SYLVA_SCENE_H
#define SYLVA_SCENE_H

#include <stdint.h>

#include "scene/canopy.h"
#include "scene/land_cover.h"
#include "scene/mesh.h"
#include "scene/scene_settings.h"
#include "util/err.h"
#include "util/name_index.h"
#include "util/vec3.h"

typedef struct material {
    char *name;               /* owned */
    sylva_bsdf bsdf;
    vec3 albedo;              /* linear RGB */
    vec3 transmittance;       /* LEAF only */
    int32_t texture;          /* index into scene.textures, or -1 */
    int alpha_mask;
} material;

typedef struct texture {
    char *name;               /* owned */
    uint32_t width, height;
    uint8_t *rgba;            /* width*height*4, row 0 at v = 1 (top); owned */
    int has_alpha;            /* some texel has alpha < 255 */
} texture;

typedef struct prototype {
    uint32_t species;         /* index into scene.species */
    uint32_t variant;
    double age;               /* normalised age this variant was built for */
    double height;            /* model height, metres */
    mesh *mesh;               /* owned; in the prototype's own frame (Z up, base at origin) */
} prototype;

typedef struct species {
    char *name;               /* owned */
    uint32_t first_prototype; /* its variants are prototypes [first, first + n_variants) */
    uint32_t n_variants;
    int ground_cover;         /* 1: grass and herbs placed around the camera (ground_cover_place.h),
                                 not plants of the scene: no canopy, no crown proxy */
    uint32_t young_stock_of;  /* 0, or 1 + the species whose planted young stock this one draws
                                 (scene_build/planting_stock.h): the same plants, young; same name */
} species;

typedef struct instance {
    uint32_t prototype;
    xform3x4 xf;              /* prototype frame → world */
    int development;          /* 1: new planting, part of the development (plants: development: true) */
    uint32_t planted;         /* 0, or the plant of the planting plan it is + 1: the same plant
                                 has the same number whatever the year (scene_build/scene_planting.h) */
} instance;

/* A mesh that several objects share: an imported model file or a part of a group. Objects
 * place it as instances, as plants place a species' prototype: 20 turbines hold one copy. */
typedef struct object_model {
    char *name;               /* owned; the file or part it came from, for messages and exports */
    mesh *mesh;               /* owned; in the model's own frame (metres, Z up) */
} object_model;

/* An object is either its own mesh in world space (scene_add_object) or an instance of a model:
 * mesh NULL, model >= 0, xf its placement. The objects section places every object, a built-in
 * shape too, as an instance of a shared model. */
typedef struct object {
    char *name;               /* owned */
    mesh *mesh;               /* owned; world space (the object's transform applied), or NULL */
    int32_t model;            /* index into scene.models when mesh is NULL, else -1 */
    xform3x4 xf;              /* model frame → world (model instances only) */
    int development;          /* 1: part of the development's coverage mask */
    uint32_t entry;           /* the objects: entry that placed it (scene_file.objects index) */
    double base;              /* z of that entry's lowest point as placed (on the ground it was
                                 snapped to, for an object standing on the terrain) */
} object;

typedef struct scene {
    site_settings site;         /* its crs_wkt and crs_name owned (copies), or NULL */
    image_settings image;
    camera_settings camera;
    sun_settings sun;
    sky_settings sky;
    earth_settings earth;
    snow_settings snow;         /* snow on the procedural ground (geometry/ground_cover.h) */
    uint32_t season_day;        /* the day of the year shown (season/phenology.h); 0: not given */
    int planting_shown;         /* 1: the planting plan stands planting_years after its year
                                   (scene_build/scene_planting.h); 0: not shown, or none */
    double planting_years, planting_year; /* years since planting shown; the plan's calendar year */

    sylva_heightfield *terrain; /* owned (with its z and material arrays), or NULL: the ground
                                   as rendered, refined around the camera */
    sylva_heightfield *surveyed; /* the ground as surveyed, which the analyses read (ZTV, probe,
                                   objects' heights, the ecology): the DTM's own nodes, the same
                                   whatever the camera. Owned when it is not terrain itself; it is
                                   terrain for an inline grid, a scene built for an analysis
                                   (build_options.analysis), and a terrain plugin older than
                                   ABI 1.5, which cannot tell it apart (docs/models/terrain_ifs.md) */
    land_cover *land_cover;     /* owned, or NULL: the class of each surveyed node from the
                                   scene's land-cover map (landcover: section) */
    canopy *canopy;             /* owned, or NULL: the canopy's height above each surveyed node
                                   (canopy: section) */
    int32_t terrain_material;   /* default material of terrain nodes without one */
    int32_t water_material;

    material *materials; uint32_t n_materials, cap_materials; /* owned */
    name_index material_names;  /* name → first material of that name; owned (its table) */
    texture *textures; uint32_t n_textures, cap_textures;     /* owned */
    species *species; uint32_t n_species;                     /* owned */
    prototype *prototypes; uint32_t n_prototypes, cap_prototypes; /* owned */
    instance *instances; uint32_t n_instances, cap_instances;  /* owned */
    object *objects; uint32_t n_objects, cap_objects;          /* owned */
    object_model *models; uint32_t n_models, cap_models;              /* owned */
    int32_t default_material;   /* grey Lambertian, always present */
} scene;

scene *scene_new(void);      /* NULL when out of memory; the default material is added */
void scene_free(scene *s);   /* accepts NULL */

/* Each returns the new element's index (>= 0) or -1 with err set (out of memory). */
int32_t scene_add_material(scene *s, const sylva_material_desc *d, err_buf *err);
int32_t scene_add_texture(scene *s, const char *name, uint32_t w, uint32_t h,
                          const uint8_t *rgba, err_buf *err); /* copies rgba */
/* A species with no variants yet (its name copied); its prototypes are the ones added next. */
int32_t scene_add_species(scene *s, const char *name, err_buf *err);
int32_t scene_add_prototype(scene *s, uint32_t species, uint32_t variant, double age,
                            double height, mesh *m, err_buf *err); /* takes m */
int32_t scene_add_instance(scene *s, uint32_t prototype, const xform3x4 *xf, err_buf *err);
int32_t scene_add_object(scene *s, const char *name, mesh *m, err_buf *err); /* takes m */
int32_t scene_add_model(scene *s, const char *name, mesh *m, err_buf *err);  /* takes m */
/* An object that places model model_index by xf (model frame → world). */
int32_t scene_add_model_object(scene *s, const char *name, uint32_t model_index, const xform3x4 *xf,
                               err_buf *err);
/* The mesh an object shows (its own, or its model's) and its transform to world space (NULL
 * when the mesh is already in world space). */
const mesh *scene_object_mesh(const scene *s, uint32_t o, const xform3x4 **xf);
/* Grows [lo, hi] by object o's world-space vertices (nothing for an object without any). */
void scene_object_bounds(const scene *s, uint32_t o, double lo[3], double hi[3]);
/* Copies site (its strings too) into s->site. Returns 0 or -1 with err set (out of memory). */
int scene_set_site(scene *s, const site_settings *site, err_buf *err);
/* The first material named `name`, or -1 (a hash lookup). */
int32_t scene_find_material(const scene *s, const char *name);

/* The material of triangle t of m: its id, or the default material where the id is -1 or names
 * no material of the scene. */
static inline uint32_t scene_triangle_material(const scene *s, const mesh *m, uint32_t t)
{
    int32_t id = m->mat[t];
    return id >= 0 && (uint32_t)id < s->n_materials ? (uint32_t)id : (uint32_t)s->default_material;
}

/* 1 when instance i is a tuft of ground cover rather than a plant of the scene. */
static inline int scene_instance_is_ground_cover(const scene *s, uint32_t i)
{
    uint32_t sp = s->prototypes[s->instances[i].prototype].species;
    return sp < s->n_species && s->species[sp].ground_cover;
}

/* The species a plant of species sp is: sp itself, or the species whose young stock sp draws. */
static inline uint32_t scene_plant_species(const scene *s, uint32_t sp)
{
    return sp < s->n_species && s->species[sp].young_stock_of ? s->species[sp].young_stock_of - 1 : sp;
}

/* The transform of a plant: translate to p, rotate by rot_deg about +Z, scale uniformly. */
xform3x4 plant_transform(const double p[3], double rot_deg, double scale);

/* The variant of `species` for normalised age t: the youngest variant at least as old as t. */
uint32_t scene_variant_for_age(const scene *s, uint32_t species, double t);
/* The variant of `species` whose model height is nearest to h metres (the lower one on a tie). */
uint32_t scene_variant_nearest_height(const scene *s, uint32_t species, double h);

/* Terrain height and unit normal at (x, y) (heightfield.h); -1 outside it or when there is no
 * terrain. The rendered ground: what plants and the camera stand on. */
int scene_terrain_height(const scene *s, double x, double y, double *z);
int scene_terrain_normal(const scene *s, double x, double y, double n[3]);

/* The same on the ground as surveyed (scene.surveyed): what every analysis reads. */
int scene_surveyed_height(const scene *s, double x, double y, double *z);
int scene_surveyed_normal(const scene *s, double x, double y, double n[3]);

#endif
