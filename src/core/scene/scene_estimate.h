/* scene_estimate.h — the memory a scene's built-in shapes will need, estimated from the scene
 * file alone, so that a scene which cannot fit (thousands of finely subdivided spheres) is
 * refused with a sentence before any mesh is built.
 *
 * Per shape: its vertex and triangle counts as shapes.c builds them, at SHAPE_VERTEX_BYTES per
 * vertex (position, normal, uv) and SHAPE_TRIANGLE_BYTES per triangle (indices, material id,
 * and the renderer's acceleration structure with its build buffers, as measured on icospheres:
 * about 160 bytes a triangle at the peak). Objects each build their own mesh; a species shape
 * is built once. Plugin geometry (trees, terrain) is not estimated here. */
#ifndef SYLVA_SCENE_ESTIMATE_H
#define SYLVA_SCENE_ESTIMATE_H

#include <stdint.h>

#include "scene/scene_file.h"

#define SHAPE_VERTEX_BYTES 32u
#define SHAPE_TRIANGLE_BYTES 128u

/* Vertices and triangles of one shape as shapes.c builds it. */
void shape_counts(const shape_spec *s, uint64_t *vertices, uint64_t *triangles);

/* 0 when the meshes of every object and species shape fit the memory budget
 * (util/memory_budget.h); otherwise -1 with err set ("file:line:column: ..." at the largest
 * contributor). */
int scene_estimate_check(const scene_file *sf, err_buf *err);

#endif
