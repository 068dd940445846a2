/* model_material.h — an imported model's materials as sylva materials: base colour, the
 * base-colour texture (a file beside the model or one embedded in it) and the alpha mask. Used
 * by model_import only; it reads the Assimp scene model_import holds.
 *
 * Ownership: a model_materials table is the caller's (model_materials_free); the materials
 * and textures it adds belong to the scene. */
#ifndef SYLVA_MODEL_MATERIAL_H
#define SYLVA_MODEL_MATERIAL_H

#include <stdint.h>

#include "scene/scene.h"
#include "util/err.h"

struct aiScene;
struct model_folder;
struct model_module;

typedef struct model_texture_use model_texture_use;

typedef struct model_materials {
    const struct aiScene *ai;  /* borrowed */
    const struct model_module *assimp; /* the model module, which reads the materials; borrowed */
    const char *path;          /* the model file, borrowed */
    const struct model_folder *folder; /* where its texture files must lie; NULL: anywhere; borrowed */
    int gltf;                  /* glTF alpha modes apply */
    int32_t *ids;              /* per Assimp material: the scene material, or -1 before use; owned */
    model_texture_use *uses;   /* textures already added, by source and alpha treatment; owned */
    uint32_t n_uses, cap_uses;
    uint32_t n_materials, n_textures; /* added to the scene so far */
} model_materials;

/* Prepares the table for ai, read by the module assimp (both must outlive it). Returns 0 or -1
 * (out of memory). */
int model_materials_init(model_materials *mm, const struct aiScene *ai, const struct model_module *assimp,
                         const char *path, int gltf, err_buf *err);
void model_materials_free(model_materials *mm); /* accepts a zeroed table */

/* The scene material for Assimp material `index`, made on first use. Returns the id (>= 0) or
 * -1 with err set (a texture that cannot be read, out of memory). */
int32_t model_material_id(model_materials *mm, scene *s, unsigned index, err_buf *err);

#endif
