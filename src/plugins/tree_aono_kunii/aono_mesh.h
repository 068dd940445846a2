/* aono_mesh.h — the geometry of a grown skeleton: bark as tapered cylinders and leaves as
 * alpha-textured quads, written into an aono_mesh_buffer (Z up, trunk base at the origin).
 *
 * Branches: each segment is a tube from its base radius to its tip radius with u around it and
 * v along it (in circumferences, so a bark texture keeps its aspect). A mother and the child
 * that continues it share one ring at the joint, cut in the plane that bisects their directions
 * (a mitre), so the bend has no gap; the other children start at the joint's centre, where
 * their open base lies inside the mother and her continuation. Tubes without a continuation
 * are capped, as are the foot of the trunk and the bases of the children of such a tube. Ring sides fall with the radius from `sides` on the
 * trunk to `min_sides`.
 *
 * Leaves: quads on the branches of the outermost leaf_levels levels, as many per metre of
 * branch as an outermost branch of the full-grown tree carries, at the bark's surface,
 * leaf_angle from the branch, the blade turned to face upward; u across the blade, v from the
 * stalk (0) to the tip (1), matching aono_leaf_texture(); the quad is leaf_length square, as the
 * leaf fills its maps' unit square.
 */
#ifndef AONO_MESH_H
#define AONO_MESH_H

#include <stdint.h>

#include "aono_config.h"
#include "aono_grow.h"
#include "aono_mesh_buffer.h"
#include "sylva/plugin.h"

/* Polygon sides of a ring of `radius`: sides * radius / trunk_radius, rounded, in
 * [min_sides, sides]. */
uint32_t aono_ring_sides(const aono_config *cfg, double radius);

/* Appends the bark of every segment with material `bark`. Returns SYLVA_OK, or a negative
 * status with err set (out of memory, the host's mesh limits). */
int aono_mesh_branches(const aono_config *cfg, const aono_skeleton *s, int32_t bark, aono_mesh_buffer *b,
                       plugin_err *err);

/* Appends leaves with material `leaf` on each leaf-bearing segment: leaf_count per
 * leaf_reference_length of its nominal length ρ (the fraction drawn at random), so that younger
 * variants, whose outermost branches are longer, stay as leafy per metre. Positions and turns
 * come from env's stream for each segment's node. Returns as above, or SYLVA_ERR_LIMIT past
 * AONO_MAX_LEAVES. */
int aono_mesh_leaves(const aono_config *cfg, const aono_skeleton *s, int32_t leaf, const aono_env *env,
                     aono_mesh_buffer *b, plugin_err *err);

/* Fills AONO_LEAF_TEXTURE_SIZE^2 RGBA8 texels (row 0 at the top, v = 1) with the leaf of the
 * config's affine maps (leaf_affine_render, seed AONO_LEAF_TEXTURE_SEED): the outline in alpha
 * (0 or 255), veins lighter than the blade; grey, so that the material's albedo sets the
 * leaf's colour. Returns 0, or -1 when out of memory. */
int aono_leaf_texture(const aono_config *cfg, uint8_t *rgba);

/* Fills AONO_BARK_TEXTURE_SIZE^2 RGBA8 texels with the config's fractal bark, one
 * circumference wide and long (the tubes' u and v). Returns 0 (the shape of
 * aono_leaf_texture, so that both are made alike). */
int aono_bark_texture(const aono_config *cfg, uint8_t *rgba);

#endif
