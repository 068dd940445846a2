/* ztv_layers.h — the GeoPackage beside a visibility map (docs/ztv.md, "The GeoPackage"), in the
 * map's CRS: the layers `viewpoints` (number, name, eye height, heading, ground level),
 * `distance_rings` (the points 1, 2, 5 and 10 km and the radius from the nearest target, each
 * ring a polygon, the distances the map itself measures) and `developments` (each structure with
 * its name, development and heights), and QGIS's `layer_styles` table holding each layer's
 * style (ztv_qml.h) as its default, so that QGIS opens them styled.
 *
 * The file is built in GDAL's memory file system and its bytes written to the stream given, so
 * that it goes to disk through the map's atomic temporaries like every other output. Its dates
 * are fixed (SYLVA_GPKG_DATE), so the same map gives the same bytes. */
#ifndef SYLVA_ZTV_LAYERS_H
#define SYLVA_ZTV_LAYERS_H

#include <stdio.h>

#include "util/err.h"
#include "ztv/ztv_raster.h"

#define SYLVA_GPKG_DATE "2000-01-01T00:00:00.000Z"
#define ZTV_RING_SEGMENTS 32 /* segments of a quarter circle of a ring */

/* The distances of the rings a map of this radius (INFINITY: none) over grid g has, ascending
 * into out (at most 5); returns how many. */
unsigned ztv_ring_distances(double radius, const ztv_grid *g, double out[5]);

/* Writes the GeoPackage of info's viewpoints, rings and structures to f. Returns 0, or -1 with
 * err set. */
int ztv_layers_write(const ztv_info *info, FILE *f, err_buf *err);

#endif
