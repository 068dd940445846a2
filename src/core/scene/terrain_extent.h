/* terrain_extent.h — where the terrain lies, for the messages that refuse a position off it:
 * its extent in local metres and, on a site, the position and the extent in map coordinates
 * (easting and northing of the site's CRS), the frame the scene file gave them in. */
#ifndef SYLVA_TERRAIN_EXTENT_H
#define SYLVA_TERRAIN_EXTENT_H

#include <stddef.h>

#include "scene/scene.h"
#include "scene/scene_file.h"

/* How far the terrain of a site may lie from the site origin, beyond its own size: a site is
 * local (docs/sites.md). */
#define TERRAIN_SITE_REACH_M 100000.0

/* ", which spans x from A to B and y from C to D (local metres)" and, on a site, "; on the
 * map (CRS) the point is at easting E, northing N and the terrain spans easting E0 to E1,
 * northing N0 to N1" for the local point (x, y), into buf; "" when s has no terrain. */
void terrain_extent_text(const scene *s, double x, double y, char *buf, size_t n);

/* On a site, refuses a terrain whose footprint lies farther from the site origin than
 * TERRAIN_SITE_REACH_M plus its own size (the larger of its width and depth): a DTM in another
 * CRS's area, or an origin given far from the DTM. Returns 0, or -1 with err (ERR_INPUT) at the
 * terrain section stating the distance in km. Nothing is checked without a site or terrain. */
int terrain_near_site(const scene *s, const scene_file *sf, err_buf *err);

#endif
