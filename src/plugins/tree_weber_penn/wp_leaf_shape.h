/* wp_leaf_shape.h — the mesh of one leaf of a species as Arbaro's leaf mesh draws it (its
 * LeafShape: disc, sphere, palm, star and the others, sized by LeafScale, LeafScaleX and
 * LeafStemLen), in the leaf's own frame: x across the blade, y its normal, z from the stalk's
 * base to the tip. wp_model.h's leaves are frames; this is the shape drawn at each. */
#ifndef WP_LEAF_SHAPE_H
#define WP_LEAF_SHAPE_H

#include <stddef.h>
#include <stdint.h>

#include "plugin_err.h"
#include "wp_params.h"

#define WP_LEAF_DISC_MAX 1000                     /* triangles of a "discN" leaf; more is refused */
#define WP_LEAF_POINTS_MAX (WP_LEAF_DISC_MAX + 2) /* points of any leaf shape */

typedef struct wp_leaf_shape {
    double (*vertex)[3];     /* owned; n_vertices, metres in the leaf's frame */
    double (*uv)[2];         /* owned; per vertex, in [0, 1]^2 across and along the blade */
    size_t n_vertices;
    uint32_t (*triangle)[3]; /* owned; n_triangles */
    size_t n_triangles;
    size_t faces;            /* Arbaro's OBJ faces for one leaf (a quad counts once) */
} wp_leaf_shape;

/* The leaf of species p (its leaf_shape, leaf_scale, leaf_scale_x, leaf_stem_len) into *out,
 * emptied first. Returns 0, or a negative sylva_status with err set and *out empty. */
int wp_leaf_shape_make(const wp_params *p, wp_leaf_shape *out, plugin_err *err);

/* The area the leaf shows seen face on, along its normal (y), in square metres: the cells of a
 * WP_LEAF_FACE_CELLS x WP_LEAF_FACE_CELLS grid over its extent in x and z whose centres some
 * triangle covers (a flat leaf's blade; a sphere's outline, not its surface). 0 for a shape
 * without extent in x or z. */
#define WP_LEAF_FACE_CELLS 256
double wp_leaf_shape_face_area(const wp_leaf_shape *s);

/* Frees what *s owns and empties it. */
void wp_leaf_shape_release(wp_leaf_shape *s);

#endif
