/* scene_trees.h — a survey's trees (the trees: section) as instances: one plant each, of its
 * species' age variant nearest to its measured height (or the one its surveyed age picks),
 * scaled so that the model is exactly as tall as the tree, and as wide as its crown when one
 * was measured (docs/trees.md gives the rule). */
#ifndef SYLVA_SCENE_TREES_H
#define SYLVA_SCENE_TREES_H

#include "scene/scene.h"
#include "scene_build/build_options.h"
#include "scene_file/scene_file.h"

/* Places sf->trees on the terrain (at z = 0 without one). Trees outside the terrain are left
 * out with a counted warning, and so are none: all of them outside is an error at the file key
 * (a survey in another place or CRS). Trees scaled above 1.5 times their species' full-grown
 * model are counted in a warning with the largest factor. Species must be built first. Returns
 * 0, or -1 with err set. */
int scene_build_trees(scene *s, const scene_file *sf, const build_options *opt, err_buf *err);

/* One plant of species t->species standing on the terrain at t->position, of the variant its
 * normalised age picks (t->age > 0) or else the one nearest its height, scaled to be t->height
 * tall (and t->crown across when above 0), turned by t->rotation_deg: a surveyed tree, and a
 * planting plan's plant at its year (scene_planting.c). Returns 0 placed, 1 when it stands
 * outside the terrain (not placed), -1 with err set. */
int scene_place_sized_tree(scene *s, const tree_spec *t, int development, err_buf *err);

#endif
