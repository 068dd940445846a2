/* wp_host_mesh.h — a grown tree (wp_model.h) as the mesh the plugin hands the host: the stems'
 * triangles with bark uv, then one leaf form (wp_leaf_form.h) at every leaf frame, in single
 * precision, with a material per triangle and smooth normals (each vertex's, the area-weighted
 * sum of its triangles' normals: the stems' rings shade round, each leaf as its form).
 *
 * Bark uv: u goes once round a stem as the model gives it, i / points; a triangle across the seam
 * (its u spanning more than half a turn) takes copies of its vertices below u 0.5 at u + 1, with
 * their normals, so the texture runs on instead of back across the whole turn. v is the model's
 * metres along the stem divided by the mean circumference of that stem level's rings, so the bark
 * texture (one circumference wide and long) keeps its aspect on every level
 * (wp_host_mesh_bark_rounds).
 *
 * Ownership: a wp_host_mesh owns its arrays; wp_host_mesh_release() frees them and accepts a
 * zeroed one. */
#ifndef WP_HOST_MESH_H
#define WP_HOST_MESH_H

#include <stdint.h>

#include "plugin_err.h"
#include "wp_leaf_form.h"
#include "wp_model.h"

#define WP_HOST_MESH_MAX_VERTICES 100000000u /* the host's per-mesh limits */
#define WP_HOST_MESH_MAX_TRIANGLES 50000000u

typedef struct wp_host_mesh {
    float *pos, *nrm, *uv;   /* owned: 3, 3 and 2 floats per vertex (normals not unit) */
    uint32_t nv;
    uint32_t *tri;           /* owned: 3 indices per triangle */
    int32_t *mat;            /* owned: material per triangle */
    uint32_t nt;
    uint32_t stem_triangles; /* the first triangles are the stems' */
    /* vertices: the model's, then the seam copies, then each leaf's */
    double top;              /* the highest vertex's z, metres (0 when empty) */
} wp_host_mesh;

/* The mean circumference of the rings of each stem level (metres; 0 where a level has none):
 * over the edges between two vertices of one ring (equal v, u apart by less than a half turn),
 * chord length over the turn between them. */
void wp_host_mesh_bark_rounds(const wp_model *m, double round[WP_LEVELS]);

/* The model's stems (material `bark`) and its leaves drawn with `leaf` (material `leaf_material`;
 * leaf NULL or without triangles: no leaves drawn) into *out (emptied first). Returns 0, or
 * SYLVA_ERR_LIMIT past the host's per-mesh limits or SYLVA_ERR_NOMEM, with err set and out empty. */
int wp_host_mesh_build(const wp_model *m, const wp_leaf_form *leaf, int32_t bark, int32_t leaf_material, wp_host_mesh *out,
                  plugin_err *err);

void wp_host_mesh_release(wp_host_mesh *w);

#endif
