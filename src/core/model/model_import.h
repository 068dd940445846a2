/* model_import.h — reading a 3-D model file (OBJ+MTL, glTF 2.0, PLY, STL, FBX, COLLADA, 3DS)
 * through Assimp into one sylva mesh in metres with Z up, its materials and textures added to
 * the scene. The node hierarchy is flattened: every node that uses a mesh adds a transformed
 * copy of it, so a mesh used by two nodes appears twice. Points and lines are dropped.
 *
 * Ownership: model_import hands back a mesh the caller frees with mesh_free; the materials and
 * textures it adds belong to the scene. Nothing global is kept between calls. */
#ifndef SYLVA_MODEL_IMPORT_H
#define SYLVA_MODEL_IMPORT_H

#include <stdint.h>

#include "model/model_limits.h"
#include "scene/mesh.h"
#include "scene/scene.h"
#include "util/err.h"

/* The up axis of the file's coordinates. Formats that state it (glTF: +Y by its
 * specification, COLLADA: <up_axis>, FBX: UpAxis, 3DS: +Z) are turned by what they state;
 * OBJ, STL and PLY state nothing and are taken as +Z unless the caller says +Y. */
typedef enum model_up {
    MODEL_UP_FILE = 0, /* what the format states; +Z for OBJ, STL and PLY */
    MODEL_UP_Y,        /* OBJ, STL, PLY only: the file is +Y up */
    MODEL_UP_Z         /* OBJ, STL, PLY only: the file is +Z up (as MODEL_UP_FILE) */
} model_up;

typedef struct model_import_options {
    double scale;           /* metres per unit after the file's own unit (COLLADA <unit>, FBX
                               UnitScaleFactor); 0 means 1; must be finite and > 0 otherwise */
    model_up up;
    uint32_t max_triangles; /* 0 means MODEL_MAX_TRIANGLES */
    const char *root;       /* the folder the model and every file it refers to must lie in
                               (model_folder.h); NULL: the model file's own folder */
} model_import_options;

/* What an import found, for messages and tests. */
typedef struct model_import_info {
    uint64_t triangles;     /* as copied: instanced meshes counted once per node */
    uint32_t meshes;        /* mesh uses (node, mesh pairs) */
    uint32_t materials;     /* materials added to the scene */
    uint32_t textures;      /* textures added to the scene */
    char missing[256];      /* the first file the model names that could not be read (a missing
                               material library, say), which the reader went on without; or "" */
} model_import_info;

/* Imports the model at path. opt may be NULL (defaults); info may be NULL. Materials are named
 * "<file name>:<material name>". Returns 0 with *out set, or -1 with err set (ERR_INPUT for a
 * missing, unreadable, truncated or unsupported file, a missing texture or a file referred to
 * outside the model's folder, ERR_LIMIT above the triangle limit, ERR_NOMEM); on failure nothing
 * is handed back, but materials and textures added before the failure stay in the scene. */
int model_import(scene *s, const char *path, const model_import_options *opt, mesh **out,
                 model_import_info *info, err_buf *err);

/* 1 when the file name's extension is one model_import reads (case does not matter). */
int model_import_supports(const char *path);

#endif
