/* scene_canopy.h — the scene's canopy (scene/canopy.h) read from the canopy: section's models
 * onto the ground as surveyed, once, for every command that builds the scene; and the woodland's
 * plants (the land cover's communities and the ecology's) fitted to it, so that the forest drawn stands as high as the survey measured it.
 *
 * Fitting, plant by plant, with H the canopy's height at the node nearest the plant's foot:
 *  - no data there: the plant is kept as grown;
 *  - H below CANOPY_OPEN: the survey saw nothing that tall there: a plant taller than that is
 *    removed, a lower one kept;
 *  - a plant that reaches the canopy (grown to at least CANOPY_REACH of H, and of a species whose
 *    full-grown model is at least H / CANOPY_STRETCH) takes the age variant whose model height is
 *    nearest H, scaled to H exactly, as a surveyed tree is (scene_trees.h); its position and turn
 *    are kept;
 *  - a lower plant, or one of a species that never grows near H, is understorey under someone
 *    else's crown and is kept as grown.
 * Plants of the development are kept. The plants: and trees: sections' plants are not fitted: a
 * hand-placed plant and a surveyed tree have their size given. */
#ifndef SYLVA_SCENE_CANOPY_H
#define SYLVA_SCENE_CANOPY_H

#include "scene/scene.h"
#include "scene_file/scene_file.h"

#define CANOPY_OPEN 0.5    /* metres: a canopy lower than this is open ground */
#define CANOPY_REACH 0.5   /* share of the canopy's height a plant must reach to be part of it */
#define CANOPY_STRETCH 1.5 /* most a species' full-grown model is scaled up to reach the canopy */

/* Reads sf's canopy heights onto s->surveyed into s->canopy (nothing without a canopy:
 * section). quiet: no summary line (warnings still print). Returns 0, or -1 with err placed at
 * the key of the file at fault. */
int scene_build_canopy(scene *s, const scene_file *sf, int quiet, err_buf *err);

/* Fits instances [first, n_instances) of s (the communities' and the ecology's plants) to s->canopy as above, when
 * the scene has a canopy and sf's canopy: section leaves fit_plants on; removed plants leave the
 * array in the order of the rest. quiet: no summary line. Returns 0. */
int scene_canopy_fit_plants(scene *s, const scene_file *sf, uint32_t first, int quiet);

#endif
