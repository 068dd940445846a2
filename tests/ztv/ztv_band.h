/* ztv_band.h — one band of a raster read whole into floats, with its size, geotransform and
 * no-data value: what the ZTV comparison tools (ztv_gdal_compare.c, ztv_canopy_compare.c) read
 * every map and model with. Header-only, for those test executables. */
#ifndef SYLVA_TEST_ZTV_BAND_H
#define SYLVA_TEST_ZTV_BAND_H

#include <gdal.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct raster {
    int nx, ny;
    double gt[6];
    int has_nodata;
    double nodata;
} raster;

/* Band b of the file at path into a new nx * ny array of floats (caller frees), with its size and
 * geotransform in *r; NULL with a message on stderr that names the tool. */
static inline float *read_band(const char *tool, const char *path, int b, raster *r)
{
    GDALDatasetH ds = GDALOpen(path, GA_ReadOnly);
    if (!ds) {
        fprintf(stderr, "%s: cannot open %s\n", tool, path);
        return NULL;
    }
    float *v = NULL;
    r->nx = GDALGetRasterXSize(ds), r->ny = GDALGetRasterYSize(ds);
    if (b > GDALGetRasterCount(ds))
        fprintf(stderr, "%s: %s has %d bands, not %d\n", tool, path, GDALGetRasterCount(ds), b);
    else if (GDALGetGeoTransform(ds, r->gt) != CE_None)
        fprintf(stderr, "%s: %s has no geotransform\n", tool, path);
    else if (!(v = malloc((size_t)r->nx * r->ny * sizeof *v)))
        fprintf(stderr, "%s: out of memory for %s\n", tool, path);
    else if (GDALRasterIO(GDALGetRasterBand(ds, b), GF_Read, 0, 0, r->nx, r->ny, v, r->nx, r->ny, GDT_Float32, 0,
                          0) != CE_None) {
        fprintf(stderr, "%s: cannot read band %d of %s\n", tool, b, path);
        free(v), v = NULL;
    }
    if (v) r->nodata = GDALGetRasterNoDataValue(GDALGetRasterBand(ds, b), &r->has_nodata);
    GDALClose(ds);
    return v;
}

#endif
