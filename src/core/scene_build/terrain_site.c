/* terrain_site.c — a site's terrain refused when it lies far from the site origin (terrain_site.h). */
#include "scene_build/terrain_site.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

int terrain_near_site(const scene *s, const scene_file *sf, err_buf *err)
{
    const sylva_heightfield *t = s->terrain;
    if (!t || !sf->site.crs_wkt) return 0;
    double x0 = t->x0, x1 = t->x0 + (t->nx - 1) * t->dx, y0 = t->y0, y1 = t->y0 + (t->ny - 1) * t->dy;
    double gap_x = fmax(fmax(x0, -x1), 0.0), gap_y = fmax(fmax(y0, -y1), 0.0);
    double distance = hypot(gap_x, gap_y), size = fmax(x1 - x0, y1 - y0);
    if (distance <= TERRAIN_SITE_REACH_M + size) return 0; /* NaN extents are the plugin's to refuse */
    const double *o = sf->site.origin;
    const char *dtm = scene_file_dtm_path(sf);
    char what[1200];
    if (dtm) snprintf(what, sizeof what, "the DTM '%s'", dtm);
    else snprintf(what, sizeof what, "the terrain");
    return err_at(err, ERR_INPUT, sf->path, sf->terrain.line, sf->terrain.column,
                  "%s lies %.0f km from the site origin (easting %.0f, northing %.0f): in the site's CRS (%s) it "
                  "spans easting %.0f to %.0f, northing %.0f to %.0f, %.1f km across; a site is local, so its "
                  "terrain must come within %.1f km of the origin (%.0f km plus the terrain's own size); check "
                  "that site: crs: is a CRS for the DTM's area and that site: origin: lies on the DTM",
                  what, distance / 1000.0, o[0], o[1], sf->site.crs_name ? sf->site.crs_name : "unnamed",
                  x0 + o[0], x1 + o[0], y0 + o[1], y1 + o[1], size / 1000.0,
                  (TERRAIN_SITE_REACH_M + size) / 1000.0, TERRAIN_SITE_REACH_M / 1000.0);
}
