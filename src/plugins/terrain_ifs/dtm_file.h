/* dtm_file.h — a DTM from a raster file: a crop window, a resampling step, nodata filling and
 * the conversion of geographic (degree) grids to metres.
 *
 * Nodes are the pixel centres of the file. A crop window is given in the file's pixels as
 * gdal_translate's -srcwin: first column, first row (row 0 is the file's first row, the north
 * edge of a north-up raster), columns, rows. The step keeps every step-th node of the window
 * in both directions, starting at its first node (surveyed heights are kept, not averaged).
 *
 * Spacing in metres: a projected grid's spacing times its linear unit; a geographic grid's
 * spacing in degrees through a local equirectangular projection at the window's centre
 * latitude phi0 on the WGS 84 ellipsoid, dx = N(phi0) cos(phi0) dlon, dy = M(phi0) dlat with N
 * and M the prime-vertical and meridional radii of curvature. A file without a coordinate
 * system is read as degrees (units: auto) when both cell sizes are at most 0.1 and the window
 * lies inside longitude [-180, 180] and latitude [-90, 90], as metres otherwise.
 */
#ifndef TERRAIN_IFS_DTM_FILE_H
#define TERRAIN_IFS_DTM_FILE_H

#include <stdint.h>

#include "dtm.h"
#include "plugin_err.h"

typedef enum ifs_units {
    IFS_UNITS_AUTO = 0,   /* from the file's coordinate system, else the rule above */
    IFS_UNITS_METRES = 1, /* the file's x/y units are metres (or its projected unit) */
    IFS_UNITS_DEGREES = 2 /* the file's x/y are longitude / latitude in degrees */
} ifs_units;

typedef struct ifs_dtm_file_options {
    uint32_t band;          /* 1-based band holding the heights */
    int has_crop;           /* 1: crop[] holds the window */
    uint32_t crop[4];       /* first column, first row, columns, rows (file pixels) */
    uint32_t step;          /* >= 1 */
    ifs_units units;
    double cell_size[2];    /* > 0: node spacing in metres along x and y, replacing the file's */
    double height_range[2]; /* plausible heights [low, high] in the file; a height outside it
                               is refused as damage. {0, 0}: the default range below */
    /* NULL, or called with the DTM's size once it is known and before anything is read or
     * allocated for it; a non-zero return (with err set) stops the read with that status. */
    int (*check_size)(void *ctx, uint32_t nx, uint32_t ny, plugin_err *err);
    void *check_ctx;
    const char *target_wkt; /* NULL, or read the file in this coordinate system (warped through a
                               GDAL VRT, bilinear, when the file's differs; crop and step then
                               count the warped raster's pixels) */
} ifs_dtm_file_options;

/* The default plausible heights of a DTM file in metres: the Dead Sea shore (-430 m) to Everest
 * (8,849 m) with a margin. A corrupted file (heights of +-1e34) fails instead of loading. */
#define IFS_DTM_HEIGHT_MIN (-500.0)
#define IFS_DTM_HEIGHT_MAX 9000.0

typedef struct ifs_dtm_file_info {
    char driver[32];        /* GDAL driver short name */
    char type_name[16];     /* sample type */
    uint32_t file_cols, file_rows;
    uint32_t window[4];     /* the window read (after step trimming): col, row, cols, rows */
    uint64_t nodata_filled; /* nodes that were nodata and were filled */
    int degrees;            /* 1: converted from degrees */
    int units_guessed;      /* 1: the file has no coordinate system; the units were inferred */
    double centre_lat;      /* degrees: latitude of the window's centre (degrees == 1) */
    double centre_x, centre_y; /* the window's centre in the file's coordinates */
    int warped;             /* 1: read through a warped VRT into target_wkt */
    double node0_x, node0_y; /* DTM node (0, 0) (the south-west node: a pixel centre) in the
                               raster's coordinates (target_wkt's when given) */
} ifs_dtm_file_info;

/* Reads the DTM. Fails with a sentence naming the file and the reason: unreadable or not a
 * raster (SYLVA_ERR_IO), band missing, crop window outside the raster, fewer than 3 x 3 nodes
 * or more than IFS_DTM_MAX_NODES after crop and step, no usable spacing, a latitude outside
 * (-89.9, 89.9) degrees, every node nodata. info may be NULL. */
int ifs_dtm_read_file(const char *path, const ifs_dtm_file_options *opt, ifs_dtm **out,
                      ifs_dtm_file_info *info, plugin_err *err);

/* Metres per degree of longitude and of latitude at latitude phi_deg (WGS 84). */
void ifs_metres_per_degree(double phi_deg, double *per_lon, double *per_lat);

#endif
