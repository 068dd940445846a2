/* geotiff_fixture.h — a north-up GeoTIFF made for a test: w x h cells of `cell` metres (or
 * degrees) from the north-west corner (x0, y0), in EPSG:epsg. Header-only, for the test
 * executables; the caller writes the cells and closes the dataset. */
#ifndef SYLVA_TEST_GEOTIFF_FIXTURE_H
#define SYLVA_TEST_GEOTIFF_FIXTURE_H

#include <gdal.h>
#include <ogr_srs_api.h>

/* The new dataset at path, or NULL. */
static inline GDALDatasetH geotiff_create(const char *path, int epsg, double x0, double y0, double cell, int w, int h,
                                          GDALDataType type)
{
    GDALAllRegister();
    GDALDriverH drv = GDALGetDriverByName("GTiff");
    GDALDatasetH ds = drv ? GDALCreate(drv, path, w, h, 1, type, NULL) : NULL;
    if (!ds) return NULL;
    double t[6] = {x0, cell, 0, y0, 0, -cell};
    GDALSetGeoTransform(ds, t);
    OGRSpatialReferenceH srs = OSRNewSpatialReference(NULL);
    OSRImportFromEPSG(srs, epsg);
    GDALSetSpatialRef(ds, srs);
    OSRDestroySpatialReference(srs);
    return ds;
}

#endif
