/* planting_ogr.h — the features of a planting plan drawn in a vector file OGR reads (GeoPackage,
 * Shapefile, GeoJSON, ...): each feature's outline, line or point in the site CRS and its
 * attributes as text. What the attributes mean (species, spacing, stock) is the scene file's to
 * judge (scene_file/scene_file_planting.c); here a feature must be a polygon (one outer ring), a
 * line or a point, and its CRS convertible into the site's. GDAL never reaches the network and
 * its messages go to err.
 *
 * Ownership: everything a read returns lives in the arena passed in. */
#ifndef SYLVA_PLANTING_OGR_H
#define SYLVA_PLANTING_OGR_H

#include <stdint.h>

#include "util/arena.h"
#include "util/err.h"

/* The attributes a plan's feature may carry, in this order in plan_shape.value. */
enum { PLAN_NAME = 0, PLAN_KIND, PLAN_SPECIES, PLAN_SHARES, PLAN_SPACING, PLAN_DENSITY, PLAN_ROWS, PLAN_ROW_SPACING,
       PLAN_STOCK, PLAN_STOCK_HEIGHT, PLAN_N_FIELDS };
extern const char *const plan_field_names[PLAN_N_FIELDS]; /* "name", "kind", "species", ... */

typedef enum plan_geometry { PLAN_POINT = 0, PLAN_LINE, PLAN_POLYGON } plan_geometry;

typedef struct plan_shape {
    plan_geometry geometry;
    double (*xy)[2]; uint32_t n_xy; /* easting, northing in the site CRS; a ring not closed */
    const char *value[PLAN_N_FIELDS]; /* NULL when the layer lacks the field or it is empty */
    const char *feature;        /* "FID 7" */
} plan_shape;

/* Reads layer (NULL: the file's only one) of path (named `shown` in messages) into shapes, in
 * the site CRS site_wkt (the file's own CRS, else `crs` when given: EPSG:NNNN or WKT). Returns
 * 0, or -1 with err set naming the file and, for a feature's fault, its FID. */
int plan_read_ogr(arena *a, const char *path, const char *shown, const char *layer, const char *crs,
                  const char *site_wkt, plan_shape **shapes, uint32_t *n, err_buf *err);

#endif
