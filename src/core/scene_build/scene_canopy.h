/* scene_canopy.h — the scene's canopy (scene/canopy.h) read from the canopy: section's models
 * onto the ground as surveyed, once, for every command that builds the scene. */
#ifndef SYLVA_SCENE_CANOPY_H
#define SYLVA_SCENE_CANOPY_H

#include "scene/scene.h"
#include "scene_file/scene_file.h"

/* Reads sf's canopy heights onto s->surveyed into s->canopy (nothing without a canopy:
 * section). quiet: no summary line (warnings still print). Returns 0, or -1 with err placed at
 * the key of the file at fault. */
int scene_build_canopy(scene *s, const scene_file *sf, int quiet, err_buf *err);

#endif
