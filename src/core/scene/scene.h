/* scene.h — the scene graph a back end renders: terrain, species prototypes (meshes, several
 * age variants per species), instances of them, objects, materials and textures, the camera,
 * sun, sky and image settings.
 *
 * Ownership: a scene owns everything in it: meshes, the terrain heightfield, textures,
 * material names and the arrays. scene_free releases it all. Settings are copied from the
 * scene_file, so a scene outlives the file it came from. There is no global state: two scenes
 * in one process are independent.
 */
#ifndef SYLVA_SCENE_H
#define SYLVA_SCENE_H

#include <stdint.h>

#include "scene/mesh.h"
#include "scene/scene_file.h"
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
} species;

typedef struct instance {
    uint32_t prototype;
    xform3x4 xf;              /* prototype frame → world */
} instance;

typedef struct object {
    char *name;               /* owned */
    mesh *mesh;               /* owned; world space (the object's transform applied) */
} object;

typedef struct scene {
    image_settings image;
    camera_settings camera;
    sun_settings sun;
    sky_settings sky;
    earth_settings earth;

    sylva_heightfield *terrain; /* owned (with its z and material arrays), or NULL */
    int32_t terrain_material;   /* default material of terrain nodes without one */
    int32_t water_material;

    material *materials; uint32_t n_materials, cap_materials; /* owned */
    name_index material_names;  /* name → first material of that name; owned (its table) */
    texture *textures; uint32_t n_textures, cap_textures;     /* owned */
    species *species; uint32_t n_species;                     /* owned */
    prototype *prototypes; uint32_t n_prototypes, cap_prototypes; /* owned */
    instance *instances; uint32_t n_instances, cap_instances;  /* owned */
    object *objects; uint32_t n_objects, cap_objects;          /* owned */
    int32_t default_material;   /* grey Lambertian, always present */
} scene;

scene *scene_new(void);      /* NULL when out of memory; the default material is added */
void scene_free(scene *s);   /* accepts NULL */

/* Each returns the new element's index (>= 0) or -1 with err set (out of memory). */
int32_t scene_add_material(scene *s, const sylva_material_desc *d, err_buf *err);
int32_t scene_add_texture(scene *s, const char *name, uint32_t w, uint32_t h,
                          const uint8_t *rgba, err_buf *err); /* copies rgba */
int32_t scene_add_prototype(scene *s, uint32_t species, uint32_t variant, double age,
                            double height, mesh *m, err_buf *err); /* takes m */
int32_t scene_add_instance(scene *s, uint32_t prototype, const xform3x4 *xf, err_buf *err);
int32_t scene_add_object(scene *s, const char *name, mesh *m, err_buf *err); /* takes m */
/* The first material named `name`, or -1 (a hash lookup). */
int32_t scene_find_material(const scene *s, const char *name);

/* The material of triangle t of m: its id, or the default material where the id is -1 or names
 * no material of the scene. */
static inline uint32_t scene_triangle_material(const scene *s, const mesh *m, uint32_t t)
{
    int32_t id = m->mat[t];
    return id >= 0 && (uint32_t)id < s->n_materials ? (uint32_t)id : (uint32_t)s->default_material;
}

/* The variant of `species` for normalised age t: the youngest variant at least as old as t. */
uint32_t scene_variant_for_age(const scene *s, uint32_t species, double t);

/* Terrain height and unit normal at (x, y) (heightfield.h); -1 outside it or when there is no
 * terrain. */
int scene_terrain_height(const scene *s, double x, double y, double *z);
int scene_terrain_normal(const scene *s, double x, double y, double n[3]);

#endif
