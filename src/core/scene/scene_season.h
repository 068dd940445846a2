/* scene_season.h — a built scene's plants as they look on the scene's day of the year. A
 * species out of leaf keeps its prototypes and every instance of them (the same plants in the
 * same places, with the same ids and transforms, as any other season of the scene); only its
 * prototypes' leaf triangles (those of a leaf material) are dropped. The crown proxies and
 * their calibration (render/crown_proxy.h) then see the bare plant: a prototype with no leaf
 * triangles has no crown and no proxy.
 *
 * Ownership: changes the scene's prototype meshes in place (each still owned by the scene). */
#ifndef SYLVA_SCENE_SEASON_H
#define SYLVA_SCENE_SEASON_H

#include "scene/scene.h"

/* Applies sf's season to s (built from sf by scene_build). Returns 0 (nothing it does can fail). */
int scene_apply_season(scene *s, const scene_file *sf);

/* Drops the triangles of m whose material is a leaf (SYLVA_BSDF_LEAF); returns how many. The
 * vertices stay, so vertex indices and the mesh's bounds are unchanged. */
uint32_t scene_drop_leaves(const scene *s, mesh *m);

#endif
