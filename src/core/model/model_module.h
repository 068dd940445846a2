/* model_module.h — what the core and the model module (sylva_model.so, built from
 * assimp_shim.cpp) hand each other. Assimp and the libraries under it are large to load, and
 * only a scene with model objects reads a model, so the core opens the module with dlopen the
 * first time a model is read (model/model_assimp.c), never at start-up.
 *
 * The module's one exported function, MODEL_MODULE_ENTRY, returns its table of operations. The
 * table begins with its size, and fields are only ever appended; MODEL_MODULE_VERSION changes
 * when one changes meaning. The scene a reading hands over is Assimp's own structures, read by
 * the core through Assimp's C headers, and lives until the reading is closed. (C_STRUCT and
 * C_ENUM are Assimp's: "struct" and "enum" in C, nothing in C++.)
 */
#ifndef SYLVA_MODEL_MODULE_H
#define SYLVA_MODEL_MODULE_H

#include <assimp/cfileio.h>
#include <assimp/material.h>
#include <assimp/scene.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define MODEL_MODULE_FILE "sylva_model.so"
#define MODEL_MODULE_ENTRY "sylva_model_module"
#define MODEL_MODULE_VERSION 1u

/* How a reading ended. */
typedef enum model_read_status {
    MODEL_READ_OK,         /* the scene, triangulated, points and lines dropped */
    MODEL_READ_FAILED,     /* Assimp refused the file: why holds its reason */
    MODEL_READ_EMPTY_FACE, /* a face of no vertices: why holds "mesh M, face F" */
    MODEL_READ_NOMEM       /* out of memory */
} model_read_status;

typedef struct model_reading model_reading; /* the module's: Assimp's importer and its scene */

/* The module's operations. */
typedef struct model_module {
    uint32_t size, version;
    /* Reads the file at path, every file opened through io: its data structure validated, then
     * (when no face is of no vertices, which Assimp's triangulation aborts the program on)
     * triangulated with points and lines dropped. *out the reading (close it whatever the
     * status; NULL only when out of memory), *scene its scene when the status is MODEL_READ_OK. */
    model_read_status (*read)(const char *path, const C_STRUCT aiFileIO *io, model_reading **out,
                              const C_STRUCT aiScene **scene, char *why, size_t n);
    void (*close)(model_reading *r);
    /* Assimp's aiGetMaterialColor, aiGetMaterialString, aiGetMaterialFloatArray and
     * aiGetMaterialTexture (without the mapping's details), as Assimp's C interface has them. */
    C_ENUM aiReturn (*material_color)(const C_STRUCT aiMaterial *m, const char *key, unsigned type, unsigned index,
                                    C_STRUCT aiColor4D *out);
    C_ENUM aiReturn (*material_string)(const C_STRUCT aiMaterial *m, const char *key, unsigned type, unsigned index,
                                     C_STRUCT aiString *out);
    C_ENUM aiReturn (*material_floats)(const C_STRUCT aiMaterial *m, const char *key, unsigned type, unsigned index,
                                     float *out, unsigned *count);
    C_ENUM aiReturn (*material_texture)(const C_STRUCT aiMaterial *m, C_ENUM aiTextureType type, unsigned index,
                                      C_STRUCT aiString *path);
} model_module;

typedef const model_module *(*model_module_entry)(void);

#ifdef __cplusplus
}
#endif
#endif
