/* shapes.h — built-in shapes (box, icosphere, quad, disk, inline mesh) as triangle meshes, for
 * objects and for species whose prototype is a shape rather than a tree plugin. */
#ifndef SYLVA_SHAPES_H
#define SYLVA_SHAPES_H

#include "scene/mesh.h"
#include "scene_file/scene_file.h"

#define SHAPE_MAX_SUBDIVISIONS 8 /* icosphere: 20 * 4^8 = 1.3M triangles */

/* Appends the shape (in its own frame) to m with material mat. Returns 0 or -1 with err set. */
int shape_build(const shape_spec *s, int32_t mat, mesh *m, err_buf *err);

#endif
