/* wp_leaf_form.h — the leaf the plugin draws at each of a tree's leaf frames (wp_model.h), in the
 * leaf's own frame (x across the blade, y its normal, z from the stalk's base to the tip): the
 * species' own LeafShape mesh (wp_leaf_shape.h), or a card, two triangles whose uv carries an
 * affine-map leaf texture (stalk at v = 0, tip at v = 1, as leaf_affine.h draws it), facing +y.
 * The card shows the texture's leaf, the box of its opaque texels, over the shape's extent
 * across and along the blade, grown or shrunk about the blade's base until the leaf it shows has
 * the shape's area: so a texture whose leaf fills little of its box (a needle twig) draws as much
 * foliage as the species' own leaf would.
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

/* What a leaf texture shows: the box of its opaque texels in uv (u across, v from the stalk) and
 * the share of that box they fill. */
typedef struct wp_leaf_texture_fit {
    double u0, u1, v0, v1;
    double fill;
} wp_leaf_texture_fit;

/* The fit of an RGBA texture of size x size texels (alpha 255 inside the leaf; row 0 at v = 1,
 * as leaf_affine_render draws it). Returns 0, or -1 when no texel is opaque. */
int wp_leaf_texture_fit_of(const uint8_t *rgba, uint32_t size, wp_leaf_texture_fit *out);

/* A card (at y = 0) whose uv spans fit's box, over the shape's extent in x and z scaled about the
 * middle of the blade's base by sqrt(shape area / (fit->fill x extent)), so that the texture's
 * leaf on it has the shape's face-on area (wp_leaf_shape_face_area). A shape without extent in
 * x or z, or a fit that fills nothing, is refused (SYLVA_ERR_PARAM, err set, out empty). */
int wp_leaf_form_card(const wp_leaf_shape *shape, const wp_leaf_texture_fit *fit, wp_leaf_form *out,
                      plugin_err *err);

void wp_leaf_form_release(wp_leaf_form *f);

#endif
