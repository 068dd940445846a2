/* wp_model.h — one Weber–Penn tree grown from a species and a seed as Arbaro 1.9 grows it: its
 * stems meshed by level as Arbaro's mesh generator meshes them, and its leaves as frames (the
 * plugin draws each leaf with the species' leaf shape or a shared leaf texture). Z up, metres,
 * the trunk's base at the origin (Arbaro's own frame; its OBJ writer swaps y and z). */
#ifndef WP_MODEL_H
#define WP_MODEL_H

#include <stddef.h>
#include <stdint.h>

#include "plugin_err.h"
#include "wp_params.h"

#define WP_GROUP_LEAVES WP_LEVELS /* the group of the leaves' faces, after the stem levels */

/* One leaf: its frame as Arbaro's leaf transformation gives it. The leaf's blade lies in the
 * plane of axis[0] (across) and axis[2] (along, from the stalk to the tip); axis[1] is its normal. */
typedef struct wp_leaf {
    double origin[3];
    double axis[3][3]; /* rows: the leaf's x, y, z axes in the tree's frame (unit vectors) */
} wp_leaf;

/* The tree. Stem triangles come from Arbaro's faces (a quad is split into two triangles, so
 * `faces` keeps Arbaro's own count per group beside the triangles). */
typedef struct wp_model {
    double (*vertex)[3];       /* owned; n_vertices, the stems' mesh points */
    double (*uv)[2];           /* owned; per vertex: u around the stem in [0, 1], v along it in metres */
    size_t n_vertices;
    uint32_t (*triangle)[3];   /* owned; n_triangles, indices into vertex */
    uint8_t *level;            /* owned; per triangle: its stem's level, 0 (trunk) to 3 */
    size_t n_triangles;
    wp_leaf *leaf;             /* owned; n_leaves */
    size_t n_leaves;
    size_t stems[WP_LEVELS];   /* stems made at each level (clones from splits included) */
    size_t faces[WP_LEVELS + 1]; /* Arbaro's OBJ faces per group: stem levels, then the leaves */
    double bbox_min[3], bbox_max[3]; /* every vertex of a face, leaves included */
    double height;             /* bbox_max[2]: the top of the tree, metres */
} wp_model;

/* Grows the species p with Arbaro's seed `seed` (java.util.Random's seed; Arbaro's default is
 * 13) into *out, emptied first. Stops with SYLVA_ERR_LIMIT and a sentence when the tree would
 * pass `max_triangles` stem triangles or `max_leaves` leaves. Returns 0, or a negative
 * sylva_status with err set and *out empty. */
int wp_model_grow(const wp_params *p, int64_t seed, size_t max_triangles, size_t max_leaves,
                  wp_model *out, plugin_err *err);

/* Frees what *m owns and empties it. */
void wp_model_release(wp_model *m);

#endif
