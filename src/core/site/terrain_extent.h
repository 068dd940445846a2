/* terrain_extent.h — where the terrain lies, for the messages that refuse a position off it:
 * its extent in local metres and, on a site, the position and the extent in map coordinates
 * (easting and northing of the site's CRS), the frame the scene file gave them in. */
#ifndef SYLVA_TERRAIN_EXTENT_H
#define SYLVA_TERRAIN_EXTENT_H

#include <stddef.h>

#include "scene/scene.h"

/* ", which spans x from A to B and y from C to D (local metres)" and, on a site, "; on the
 * map (CRS) the point is at easting E, northing N and the terrain spans easting E0 to E1,
 * northing N0 to N1" for the local point (x, y), into buf; "" when s has no terrain. */
void terrain_extent_text(const scene *s, double x, double y, char *buf, size_t n);

#endif
