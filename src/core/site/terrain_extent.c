/* terrain_extent.c — the terrain's extent and a point, in local metres and on the site's map. */
#include "site/terrain_extent.h"

#include <stdio.h>

void terrain_extent_text(const scene *s, double x, double y, char *buf, size_t n)
{
    const sylva_heightfield *t = s->terrain;
    if (!n) return;
    buf[0] = '\0';
    if (!t) return;
    double x0 = t->x0, x1 = t->x0 + (t->nx - 1) * t->dx, y0 = t->y0, y1 = t->y0 + (t->ny - 1) * t->dy;
    int k = snprintf(buf, n, ", which spans x from %.3f to %.3f and y from %.3f to %.3f (local metres)", x0, x1,
                     y0, y1);
    if (!s->site.crs_wkt || k < 0 || (size_t)k >= n) return;
    const double *o = s->site.origin;
    snprintf(buf + k, n - (size_t)k,
             "; on the map (%s) the point is at easting %.3f, northing %.3f and the terrain spans easting %.3f "
             "to %.3f, northing %.3f to %.3f",
             s->site.crs_name ? s->site.crs_name : "the site's CRS", x + o[0], y + o[1], x0 + o[0], x1 + o[0],
             y0 + o[1], y1 + o[1]);
}
