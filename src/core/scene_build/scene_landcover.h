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

/* The shares of the SYLVA_COVER_* kinds (sylva/plugin.h) of sf's land-cover map within 5 km of
 * the site origin, read on a 100 m grid, over the ground the map covers there; the terrain
 * plugin's `biome: auto` reads them. Returns 1 with shares set, 0 when the scene has no
 * land-cover map or site, or the map covers none of that square (the full read that follows
 * reports what is wrong with the map). */
int scene_landcover_shares(const scene_file *sf, double shares[SYLVA_COVER_KINDS]);

#endif
