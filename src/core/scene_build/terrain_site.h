/* terrain_site.h — a site's terrain checked against the site once it is built: a DTM in another
 * CRS's area, or an origin given far from the DTM, is refused at the terrain section of the
 * scene file. */
#ifndef SYLVA_TERRAIN_SITE_H
#define SYLVA_TERRAIN_SITE_H

#include "scene/scene.h"
#include "scene_file/scene_file.h"
#include "util/err.h"

/* How far the terrain of a site may lie from the site origin, beyond its own size: a site is
 * local (docs/sites.md). */
#define TERRAIN_SITE_REACH_M 100000.0

/* On a site, refuses a terrain whose footprint lies farther from the site origin than
 * TERRAIN_SITE_REACH_M plus its own size (the larger of its width and depth): a DTM in another
 * CRS's area, or an origin given far from the DTM. Returns 0, or -1 with err (ERR_INPUT) at the
 * terrain section stating the distance in km. Nothing is checked without a site or terrain. */
int terrain_near_site(const scene *s, const scene_file *sf, err_buf *err);

#endif
