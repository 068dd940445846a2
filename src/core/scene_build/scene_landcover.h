/* scene_landcover.h — the scene's land cover (scene/land_cover.h) read from the landcover:
 * section's map onto the ground as surveyed, once, for every command that builds the scene. */
#ifndef SYLVA_SCENE_LANDCOVER_H
#define SYLVA_SCENE_LANDCOVER_H

#include "scene/scene.h"
#include "scene_file/scene_file.h"

/* Reads sf's land-cover map onto s->surveyed into s->land_cover (nothing without a landcover:
 * section). quiet: no summary line (warnings still print). Returns 0, or -1 with err placed at
 * the map's key. */
int scene_build_landcover(scene *s, const scene_file *sf, int quiet, err_buf *err);

#endif
