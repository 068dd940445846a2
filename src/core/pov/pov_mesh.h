/* pov_mesh.h — a mesh as a POV-Ray mesh2 declaration: vertex positions, the shading normals,
 * uv coordinates when a textured material needs them, and a texture per triangle (one texture
 * for the whole mesh, or a texture_list when it uses several materials). Material ids resolve
 * as the renderer resolves them (scene_triangle_material).
 * Textures are referred to by the identifiers of pov_names.h, declared elsewhere. */
#ifndef SYLVA_POV_MESH_H
#define SYLVA_POV_MESH_H

#include "pov/pov_file.h"
#include "scene/mesh.h"
#include "scene/scene.h"
#include "util/err.h"

/* Writes `#declare ident = mesh2 { ... }` for m (which must have triangles), its textures from
 * its materials, or `texture_ident` on every triangle when that is not NULL. Returns
 * 0, or -1 with err set when a position, normal or uv is not finite or memory runs out. */
int pov_write_mesh(pov_file *pf, const char *ident, const mesh *m, const scene *s, const char *texture_ident,
                   err_buf *err);

#endif
