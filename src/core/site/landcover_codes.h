/* landcover_codes.h — the map's own codes at every node of the site's grid, before a legend
 * gives them names and kinds: what the raster reader (landcover_raster.c) and the polygon
 * reader (landcover_polygons.c) hand to the classifier (landcover_classes.c), and the node
 * coordinates they share (landcover_nodes.c). Internal to site/landcover*.c.
 *
 * Ownership: a landcover_codes owns its code array and its names; landcover_codes_release
 * frees them. */
#ifndef SYLVA_LANDCOVER_CODES_H
#define SYLVA_LANDCOVER_CODES_H

#include <stdint.h>
#include <stdio.h>

#include <gdal.h>
#include <ogr_api.h>
#include <ogr_srs_api.h>

#include "scene/land_cover.h"
#include "site/landcover_source.h"
#include "util/err.h"

#define LANDCOVER_NO_CODE INT32_MIN /* a node off the map, or on a no-data cell */

typedef struct landcover_name {
    int64_t code;
    char *name;             /* owned */
} landcover_name;

typedef struct landcover_codes {
    int32_t *code;          /* nx * ny, row j = 0 south; owned */
    landcover_name *names;  /* the class names the map carries (raster categories or attribute
                               table, a text class field), or NULL; owned */
    uint32_t n_names;
    double centre_lonlat[2]; /* the map's centre, longitude and latitude */
    int has_centre;
    uint64_t covered;       /* nodes inside the map's extent (raster) or a polygon */
} landcover_codes;

void landcover_codes_release(landcover_codes *c);
/* Adds (code, a copy of name) to c->names. 0, or -1 with err set (out of memory). */
int landcover_codes_add_name(landcover_codes *c, int64_t code, const char *name, err_buf *err);
/* The name the map gives code, or NULL. */
const char *landcover_codes_name(const landcover_codes *c, int64_t code);

/* The site CRS as GDAL's spatial reference, axes in GIS order (easting, northing); NULL with err
 * set. The caller releases it (OSRRelease). */
OGRSpatialReferenceH landcover_site_srs(const landcover_grid *g, err_buf *err);

/* Every node's map coordinates in `map_srs` (axes in GIS order): x[k], y[k] for node k = j nx + i,
 * both HUGE_VAL where the node cannot be converted. x and y are malloc'ed (the caller frees them).
 * 0, or -1 with err set. */
int landcover_node_coords(const landcover_grid *g, OGRSpatialReferenceH map_srs, double **x, double **y,
                          err_buf *err);

/* The longitude and latitude of (x, y) of map_srs into c->centre_lonlat (has_centre stays 0 when
 * it cannot be converted). */
void landcover_codes_centre(landcover_codes *c, OGRSpatialReferenceH map_srs, double x, double y);

/* The two readers: fill c for the grid. 0, or -1 with err set. */
int landcover_raster_codes(const landcover_source *src, const landcover_grid *g, landcover_codes *c, err_buf *err);
int landcover_polygon_codes(const landcover_source *src, const landcover_grid *g, landcover_codes *c,
                            err_buf *err);

/* The layer of an open vector dataset the source names (its `layer`, or the first) and the index
 * of its class field in *field; NULL with err set and *fault naming the key at fault. */
OGRLayerH landcover_polygon_layer(GDALDatasetH ds, const landcover_source *src, int *field, landcover_fault *fault,
                                  err_buf *err);

/* The land cover from the codes: the legend (auto chosen here), the scene's classes, a warning
 * for codes the legend lacks on warnings and the summary line on summary (either NULL: none). NULL with err set. */
land_cover *landcover_classify(const landcover_source *src, const landcover_grid *g, landcover_codes *c,
                               FILE *warnings, FILE *summary, err_buf *err);

#endif
