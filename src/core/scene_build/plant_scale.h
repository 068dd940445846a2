/* plant_scale.h — a plant of a species made as tall as a measured or chosen height: its model
 * (the age variant nearest that height, scene_variant_nearest_height) scaled to it exactly, and
 * as wide as a measured crown when there is one (within half and twice the vertical scale). The surveyed trees
 * (scene_trees.c) and the land cover's communities (scene_communities.c) are sized this way. */
#ifndef SYLVA_PLANT_SCALE_H
#define SYLVA_PLANT_SCALE_H

#include <stdint.h>

#include "scene/scene.h"

/* The scales (vertical, horizontal) that make the model pr `height` metres tall and, with
 * crown > 0, `crown` metres across; pr->height must be above 0. */
void plant_scales(const prototype *pr, double height, double crown, double *vertical, double *horizontal);

#endif
