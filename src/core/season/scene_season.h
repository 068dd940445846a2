/* scene_season.h — a built scene's plants as they look on the scene's day of the year. Every
 * species keeps its prototypes and every instance of them (the same plants in the same places,
 * with the same ids and transforms, as any other season of the scene): out of leaf, only its
 * prototypes' leaf triangles (those of a leaf material) are dropped; in autumn colour, only its
 * leaf triangles' materials change (to copies of its own), and a share of its leaves (whole
 * leaves, the same ones whatever the thread count) is already down. The crown proxies and
 * their calibration (render/crown_proxy.h) then see the bare plant: a prototype with no leaf
 * triangles has no crown and no proxy.
 *
 * Ownership: changes the scene's prototype meshes in place and adds materials (all owned by the
 * scene). */
#ifndef SYLVA_SCENE_SEASON_H
#define SYLVA_SCENE_SEASON_H

#include <stdint.h>

#include "season/phenology.h"
#include "scene/scene.h"

/* Applies the season on `day` (a day of the year) to species i of s, whose leaves follow p: out
 * of leaf, it loses its leaf triangles; with its leaves turning (phenology_autumn_share > 0), it
 * gets its own copy of each leaf material of its prototypes, albedo and transmittance moved that
 * share of the way toward its autumn colour, and loses the leaves already down
 * (phenology_fallen_share). Returns 0, or -1 with err set (out of memory). */
int scene_apply_season(scene *s, uint32_t i, const phenology *p, uint32_t day, err_buf *err);

/* Drops the triangles of m whose material is a leaf (SYLVA_BSDF_LEAF); returns how many. The
 * vertices stay, so vertex indices and the mesh's bounds are unchanged. */
uint32_t scene_drop_leaves(const scene *s, mesh *m);

/* Drops the leaves of m that are down when share (0..1) of them has fallen. A leaf is a set of
 * leaf triangles joined by shared vertices (a plugin's leaf quad, an imported leaf's fan); it
 * is down when a number in [0, 1) drawn from a hash of key and its first triangle's index is
 * below share, so the same leaves fall whatever the thread count, and a leaf down at one share
 * is down at every larger one. key names the prototype (scene_leaf_fall_key). The vertices
 * stay, as in scene_drop_leaves. Returns 0 with *dropped set to the triangles dropped, or -1 with
 * err set (out of memory). */
int scene_drop_fallen_leaves(const scene *s, mesh *m, uint64_t key, double share, uint32_t *dropped,
                             err_buf *err);

/* Gives species sp's leaf triangles their own copies of their leaf materials (one per material
 * used), each albedo share f of the way toward colour c, the copies named "(species, label)":
 * autumn colour, or spring's fresh green. Returns 0, or -1 with err set. */
int scene_turn_leaves(scene *s, uint32_t sp, const char *label, const double c[3], double f, err_buf *err);

/* The leaf-fall key of variant v of the species named species_name. */
uint64_t scene_leaf_fall_key(const char *species_name, uint32_t v);

#endif
