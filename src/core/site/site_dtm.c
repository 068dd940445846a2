/* site_dtm.c — a DTM's CRS and footprint centre through GDAL's C API, quietly and offline
 * (gdal_offline.h). */
#include "site/site_dtm.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include "site/gdal_offline.h"
#include "util/file_check.h"

/* Fills d from an open dataset; 0 or -1 with err set. */
static int read_dataset(GDALDatasetH ds, const char *path, site_dtm *d, err_buf *err)
{
    double t[6];
    if (GDALGetGeoTransform(ds, t) != CE_None)
        return err_set(err, "the DTM '%s' has no georeferencing (no geotransform); give site: crs: "
                       "and origin: by hand, or georeference the file", path);
    if (t[2] != 0.0 || t[4] != 0.0)
        return err_set(err, "the DTM '%s' is a rotated grid; only north-up grids are read", path);
    double nx = GDALGetRasterXSize(ds), ny = GDALGetRasterYSize(ds);
    d->centre[0] = t[0] + 0.5 * nx * t[1];
    d->centre[1] = t[3] + 0.5 * ny * t[5];
    OGRSpatialReferenceH srs = GDALGetSpatialRef(ds);
    if (!srs) return 0;
    char *wkt = NULL;
    const char *const options[] = {"FORMAT=WKT2_2019", NULL};
    if (OSRExportToWktEx(srs, &wkt, options) != OGRERR_NONE || !wkt) {
        CPLFree(wkt);
        return err_set(err, "the DTM '%s' has a CRS GDAL cannot write as WKT; give site: crs:", path);
    }
    const char *name = OSRGetName(srs);
    d->crs_wkt = strdup(wkt);
    d->crs_name = strdup(name ? name : "unnamed");
    CPLFree(wkt);
    if (!d->crs_wkt || !d->crs_name) return err_nomem(err, "out of memory reading the DTM's CRS");
    d->geographic = OSRIsGeographic(srs) != 0;
    return 0;
}

int site_dtm_read(const char *path, site_dtm *d, err_buf *err)
{
    memset(d, 0, sizeof *d);
    if (file_is_gdal_virtual(path))
        return err_set(err, "the site's CRS is read from the DTM, but '%s' is not a local file; give "
                       "site: crs: (EPSG:NNNN or WKT)", path);
    if (file_check_regular(path, NULL, err)) return err_prefix(err, "the DTM: ");
    gdal_offline g;
    GDALDatasetH ds = gdal_offline_open(path, GDAL_OF_RASTER, &g);
    int rc = ds ? read_dataset(ds, path, d, err)
                : err_set(err, "the DTM '%s' is not a raster GDAL reads (GeoTIFF, ESRI ASCII grid, "
                          "...), or it is damaged", path);
    gdal_offline_close(ds, &g);
    if (rc) site_dtm_release(d);
    return rc;
}

void site_dtm_release(site_dtm *d)
{
    if (!d) return;
    free(d->crs_wkt);
    free(d->crs_name);
    d->crs_wkt = d->crs_name = NULL;
}
