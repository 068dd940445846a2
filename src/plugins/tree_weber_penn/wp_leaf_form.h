/* wp_leaf_form.h — the leaf the plugin draws at each of a tree's leaf frames (wp_model.h), in the
 * leaf's own frame (x across the blade, y its normal, z from the stalk's base to the tip): the
 * species' own LeafShape mesh (wp_leaf_shape.h), or a card, two triangles over that shape's
 * extent across and along the blade, whose uv carries an affine-map leaf texture (stalk at
 * v = 0, tip at v = 1, as leaf_affine.h draws it), facing +y.
 *
 * Ownership: a wp_leaf_form owns its arrays; wp_leaf_form_release() frees them and accepts a
 * zeroed form. */
#ifndef WP_LEAF_FORM_H
#define WP_LEAF_FORM_H

#include <stdint.h>

#include "plugin_err.h"
#include "wp_leaf_shape.h"

typedef struct wp_leaf_form {
    double (*vertex)[3]; /* owned; nv points, metres in the leaf's frame */
    double (*uv)[2];     /* owned; nv */
    double (*normal)[3]; /* owned; nv: the area-weighted sum of each vertex's triangles' normals */
    uint32_t nv;
    uint32_t (*tri)[3];  /* owned; nt */
    uint32_t nt;
} wp_leaf_form;

/* The shape itself. Returns 0, or a negative sylva_status with err set (out empty). */
int wp_leaf_form_own(const wp_leaf_shape *shape, wp_leaf_form *out, plugin_err *err);

/* A card over the shape's extent in x and z (at y = 0). A shape without extent in x or z is
 * refused (SYLVA_ERR_PARAM, err set, out empty). */
int wp_leaf_form_card(const wp_leaf_shape *shape, wp_leaf_form *out, plugin_err *err);

void wp_leaf_form_release(wp_leaf_form *f);

#endif
