/* cutout_outline.h — alpha-masked leaves as opaque outline polygons, for the cross-check.
 *
 * A renderer that continues a ray through a transparent texel as a new ray (POV-Ray does, for
 * camera and shadow rays alike) spends nearly all its time in a forest of leaf cards: on the
 * default scene 97 % of POV-Ray's trace time went to shadow rays crossing the cards' clear
 * texels. In outline mode every cut-out triangle (geometry/cutout.h) of the scene's meshes is
 * replaced by the part of its texture's outline it holds, and the material is drawn opaque;
 * the export and the verification render both take the changed scene, so they still see the
 * same surface.
 *
 * The outline of a texture is a convex polygon in uv: the convex hull of its kept texels
 * (cutout_texel_kept), cut down to at most CUTOUT_OUTLINE_CORNERS corners by dropping, one at a
 * time, the corner whose removal loses least area, then scaled about its centroid to the kept
 * texels' area (so a crown blocks about as much light as with the mask). A cut-out triangle keeps
 * the polygon clipped to the triangle's uvs; each corner of the clipped part takes the
 * position, normal and uv interpolated by its barycentrics, and the part is cut into a fan.
 * The leaves' shapes become coarser (a spray of leaves one convex patch, a sprig of needles a
 * small diamond); what is compared is the renderers, not the leaf shapes. */
#ifndef SYLVA_CUTOUT_OUTLINE_H
#define SYLVA_CUTOUT_OUTLINE_H

#include <stdint.h>

#include "scene/scene.h"
#include "util/err.h"

#define CUTOUT_OUTLINE_CORNERS 8

/* A texture's outline: n corners (u, v), counter-clockwise; n is 0 when no texel is kept. */
typedef struct cutout_outline {
    float uv[CUTOUT_OUTLINE_CORNERS][2];
    int n;
} cutout_outline;

/* The outline of texture t's kept texels. */
void cutout_outline_of_texture(const texture *t, cutout_outline *out);

/* Cut-out triangles over the scene's plant variants, models and objects. */
uint64_t cutout_outline_triangles_in(const scene *s);

typedef struct cutout_outline_stats {
    uint64_t cutout_triangles; /* replaced */
    uint64_t outline_triangles; /* put in their place */
    uint32_t materials;         /* cut-out materials drawn opaque */
} cutout_outline_stats;

/* Replaces every cut-out triangle of s's plant variants, models and objects by its part of the
 * outline and turns the cut-out materials' masks off. Returns 0, or -1 with err set (out of
 * memory, a mesh over its limits); s is then partly changed and must be freed. */
int cutout_outline_scene(scene *s, cutout_outline_stats *st, err_buf *err);

/* How a command draws cut-outs: as their masks, as outlines, or (auto) as outlines when the
 * scene holds more than CUTOUT_OUTLINE_AUTO_TRIANGLES cut-out triangles (a forest, where POV-Ray
 * would take hours) and as masks otherwise (the small test scenes check the masks exactly). */
typedef enum leaf_mode { LEAF_MODE_AUTO, LEAF_MODE_MASK, LEAF_MODE_OUTLINE } leaf_mode;
#define CUTOUT_OUTLINE_AUTO_TRIANGLES 200000u

/* Applies mode to s: returns 1 when its cut-outs were drawn as outlines (st filled), 0 when
 * left as masks, -1 with err set on failure. */
int cutout_outline_apply(scene *s, leaf_mode mode, cutout_outline_stats *st, err_buf *err);

#endif
