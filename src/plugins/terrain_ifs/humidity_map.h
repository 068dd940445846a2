/* humidity_map.h — a humidity map for the ground cover: one band of a raster (any raster GDAL
 * reads: a GeoTIFF, a PNG such as the humidity map `sylva factors` writes for the ecology, ...)
 * whose pixels tile the terrain's footprint exactly, north up (the first row is the northern
 * edge, as in any image). Raw values map linearly to humidity: from `range` when given
 * (range[0] -> 0, range[1] -> 1), otherwise integer samples are divided by their type's largest
 * value (255 for 8-bit, 65535 for 16-bit) and floating samples are used as they are. Results are
 * clamped to [0, 1]; nodata counts as humid (1). The map is sampled bilinearly between pixel
 * centres at each output node (clamped at the edges), so its size need not match the grid. */
#ifndef TERRAIN_IFS_HUMIDITY_MAP_H
#define TERRAIN_IFS_HUMIDITY_MAP_H

#include <stdint.h>

#include "plugin_err.h"

#define IFS_HUMIDITY_MAX_PIXELS (1u << 26) /* 67 M pixels: the largest map read */

typedef struct ifs_humidity_source {
    const char *path;
    uint32_t band;          /* 1-based */
    int has_range;          /* 1: range[] maps raw values to [0, 1] */
    double range[2];        /* raw value of humidity 0 and of humidity 1; different */
} ifs_humidity_source;

/* Fills out (nx * ny, row 0 south) with the map's humidity at each node of an nx x ny grid
 * spanning the footprint. */
int ifs_humidity_read(const ifs_humidity_source *src, uint32_t nx, uint32_t ny, float *out,
                      plugin_err *err);

#endif
