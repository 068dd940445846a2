/* site_frame.h — where a scene stands on the Earth: the site's coordinate reference system
 * (through PROJ) and the local frame around the site origin.
 *
 * The site CRS must be projected with metre axes (east, north): the renderer works in metres,
 * and a geographic CRS (degrees) or a CRS in feet would distort every distance. A site frame
 * converts points given in another CRS (longitude/latitude, a DTM's own CRS) into the site CRS;
 * local coordinates are then map - origin (docs/sites.md), computed in double precision.
 *
 * PROJ runs in a context of the frame's own, with network access off and its log silent, so two
 * frames never share state and no lookup leaves the machine.
 *
 * Ownership: site_frame_new allocates the frame, its PROJ objects and its strings;
 * site_frame_free releases them all. */
#ifndef SYLVA_SITE_FRAME_H
#define SYLVA_SITE_FRAME_H

#include "util/err.h"

typedef struct site_frame site_frame;

/* A frame for the CRS given as "EPSG:NNNN", "EPSG:NNNN+MMMM" (with a vertical CRS, whose
 * horizontal part is the one checked) or as WKT (1 or 2). A CRS that is not projected in
 * metres is refused with a sentence that suggests a UTM zone: the zone of `near_lonlat`
 * (longitude, latitude) when not NULL. Returns the frame (free with site_frame_free) or NULL
 * with err set (the message names the CRS as given; the caller adds where it was given). */
site_frame *site_frame_new(const char *crs_text, const double *near_lonlat, err_buf *err);
void site_frame_free(site_frame *f); /* accepts NULL */

/* The CRS as WKT2 and its short name ("WGS 84 / UTM zone 14N"); owned by the frame. */
const char *site_frame_wkt(const site_frame *f);
const char *site_frame_name(const site_frame *f);

/* Converts longitude and latitude (degrees, WGS 84, EPSG:4326) into the site CRS:
 * map[0] easting, map[1] northing, in metres. Returns 0 or -1 with err set. */
int site_frame_from_lonlat(site_frame *f, double lon, double lat, double map[2], err_buf *err);

/* The inverse: the map point (easting, northing) of the site CRS as lonlat[0] longitude and
 * lonlat[1] latitude (degrees, WGS 84). Returns 0 or -1 with err set. */
int site_frame_to_lonlat(site_frame *f, double easting, double northing, double lonlat[2],
                         err_buf *err);

/* Converts (x, y) given in the CRS `from_crs` (EPSG:NNNN or WKT; axes in GIS order: easting
 * then northing, or longitude then latitude) into the site CRS. Returns 0 or -1 with err set. */
int site_frame_from_crs(site_frame *f, const char *from_crs, double x, double y, double map[2],
                        err_buf *err);

/* The EPSG code of the WGS 84 UTM zone holding (lon, lat): 32601..32660 north of the equator,
 * 32701..32760 south of it. */
int site_utm_epsg(double lon, double lat);

#endif
