/* raster_gdal.h — one band of a raster file read through GDAL (GeoTIFF, ESRI ASCII grid, PNG,
 * and whatever else the installed GDAL reads): its size, georeferencing, coordinate-system
 * kind, nodata value, scale and offset, and its rows as metres-or-whatever numbers.
 *
 * GDAL's own messages never reach stderr: each call silences GDAL's error handler on the
 * calling thread for its duration and turns GDAL's last message into the failure sentence.
 * Ownership: an ifs_raster holds the open dataset until ifs_raster_close (which accepts a
 * raster that failed to open or was already closed). */
#ifndef TERRAIN_IFS_RASTER_GDAL_H
#define TERRAIN_IFS_RASTER_GDAL_H

#include <stdint.h>

#include "plugin_err.h"

typedef enum ifs_crs_kind {
    IFS_CRS_NONE = 0,      /* no coordinate system in the file */
    IFS_CRS_GEOGRAPHIC = 1,/* longitude / latitude in degrees */
    IFS_CRS_PROJECTED = 2, /* projected, linear units (see metres_per_unit) */
    IFS_CRS_OTHER = 3      /* anything else (local, geocentric...) */
} ifs_crs_kind;

typedef struct ifs_raster {
    void *dataset;            /* GDALDatasetH, owned: the file, or the warped VRT over it */
    void *source;             /* GDALDatasetH of the file under a warped VRT, owned; or NULL */
    int warped;               /* 1: read through a warped VRT into the target CRS */
    void *band;               /* GDALRasterBandH of the band asked for (borrowed from dataset) */
    uint32_t cols, rows;      /* raster size in pixels; row 0 is the file's first row */
    uint32_t bands;
    int has_transform;        /* 1: geotransform read from the file */
    double transform[6];      /* GDAL geotransform: x = t0 + col t1 + row t2, y = t3 + col t4 + row t5
                                 (pixel corners); (0,1,0,0,0,1) when absent */
    ifs_crs_kind crs;
    double metres_per_unit;   /* IFS_CRS_PROJECTED: linear unit in metres; 1 otherwise */
    int has_nodata;
    double nodata;
    double scale, offset;     /* value = raw * scale + offset (1 and 0 when the file gives none) */
    char driver[32];          /* GDAL driver short name, e.g. "GTiff", "AAIGrid" */
    char type_name[16];       /* sample type, e.g. "Int16", "Float32" */
    double type_max;          /* largest value of an integer sample type (0 for floating types) */
    uint32_t block_rows;      /* rows of the band's blocks */
    uint32_t cached_block;    /* block row the last read went through (UINT32_MAX: none) */
    int network;              /* 1: the path names a GDAL virtual source, which may use the
                                 network; 0: GDAL's network access is off for this raster */
} ifs_raster;

/* Opens band `band` (1-based) of `path`. `what` names the file's role in messages ("DTM",
 * "humidity map"). Fails with SYLVA_ERR_IO when the file cannot be read or is not a raster,
 * SYLVA_ERR_PARAM when the band does not exist. */
int ifs_raster_open(const char *path, uint32_t band, const char *what, ifs_raster *r, plugin_err *err);

/* As ifs_raster_open, and when target_wkt is not NULL and names another coordinate system than
 * the file's, the raster is read through a GDAL warped VRT into target_wkt (bilinear
 * resampling, GDAL's choice of pixel size and extent; pixels the file does not cover are
 * nodata). A file without a coordinate system cannot be warped and is refused. */
int ifs_raster_open_in(const char *path, uint32_t band, const char *what, const char *target_wkt,
                       ifs_raster *r, plugin_err *err);
void ifs_raster_close(ifs_raster *r);

/* Reads `count` pixels of file row `row` from column `col` as doubles, converted with scale and
 * offset; nodata pixels (and NaN) become NaN. GDAL's cached blocks of a band are dropped when a
 * read moves on to another row of blocks, so reading a raster row by row holds one row of
 * blocks, not as many as GDAL's cache (5 % of the machine's memory) can take. */
int ifs_raster_read_row(ifs_raster *r, uint32_t row, uint32_t col, uint32_t count, double *out,
                        const char *what, plugin_err *err);

#endif
