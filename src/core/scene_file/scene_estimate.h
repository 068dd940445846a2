/* scene_estimate.h — the memory a scene's objects and built-in shapes will need, estimated from
 * the scene file alone, so that a scene which cannot fit (thousands of finely subdivided
 * spheres, tens of millions of placements) is refused with a sentence before any mesh is built.
 *
 * Per distinct shape (the same kind, keys and material: scene_file/shape_index.h, as the scene builds
 * it once and places it as instances): its vertex and triangle counts as shapes.c builds them,
 * at SHAPE_VERTEX_BYTES per vertex (position, normal, uv) and SHAPE_TRIANGLE_BYTES per triangle
 * (indices, material id, and the renderer's acceleration structure with its build buffers, as
 * measured on icospheres: about 160 bytes a triangle at the peak); a group part's shape and a
 * species shape are built once. Per placement (an object, or a part of a placed group), of a
 * shape or a model alike: OBJECT_PLACEMENT_BYTES. Plugin geometry (trees, terrain) and model
 * files' meshes are not estimated here (models are counted as they are read). */
#ifndef SYLVA_SCENE_ESTIMATE_H
#define SYLVA_SCENE_ESTIMATE_H

#include <stdint.h>

#include "scene_file/scene_file_spec.h"

#define SHAPE_VERTEX_BYTES 32u
#define SHAPE_TRIANGLE_BYTES 128u
/* The objects entry as read (a layout row and its name), the scene's object and its name, its
 * Embree instance and its share of the top BVH with the build's transients: 1.05 KB a placement
 * measured at the peak of `sylva render` on 10^5 and 10^6 boxes (docs/scale.md). */
#define OBJECT_PLACEMENT_BYTES 1100u

/* Vertices and triangles of one shape as shapes.c builds it. */
void shape_counts(const shape_spec *s, uint64_t *vertices, uint64_t *triangles);

/* 0 when the shapes' meshes and the placements fit the memory budget (util/memory_budget.h);
 * otherwise -1 with err set ("file:line:column: ..." at the largest shape, or at the entry with
 * the most placements when they weigh more). */
int scene_estimate_check(const scene_file *sf, err_buf *err);

#endif
