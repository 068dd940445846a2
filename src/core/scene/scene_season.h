/* scene_season.h — a built scene's plants as they look on the scene's day of the year. Every
 * species keeps its prototypes and every instance of them (the same plants in the same places,
 * with the same ids and transforms, as any other season of the scene): out of leaf, only its
 * prototypes' leaf triangles (those of a leaf material) are dropped; in autumn colour, only its
 * leaf triangles' materials change (to copies of its own). The crown proxies and
 * their calibration (render/crown_proxy.h) then see the bare plant: a prototype with no leaf
 * triangles has no crown and no proxy.
 *
 * Ownership: changes the scene's prototype meshes in place and adds materials (all owned by the
 * scene). */
#ifndef SYLVA_SCENE_SEASON_H
#define SYLVA_SCENE_SEASON_H

#include "scene/scene.h"

/* Applies sf's season to s (built from sf by scene_build): a species out of leaf loses its leaf
 * triangles; a species whose leaves are turning (phenology_autumn_share > 0) gets its own copy
 * of each leaf material of its prototypes, albedo and transmittance moved that share of the way
 * toward its autumn colour. Returns 0, or -1 with err set (out of memory). */
int scene_apply_season(scene *s, const scene_file *sf, err_buf *err);

/* Drops the triangles of m whose material is a leaf (SYLVA_BSDF_LEAF); returns how many. The
 * vertices stay, so vertex indices and the mesh's bounds are unchanged. */
uint32_t scene_drop_leaves(const scene *s, mesh *m);

#endif
