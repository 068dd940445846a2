/* site_dtm.c — a DTM's CRS and footprint centre through GDAL's C API, quietly and offline: the
 * thread's /vsicurl/ sees one impossible file name and every HTTP fetch is refused while the
 * file is open. */
#include "site/site_dtm.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_http.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include "util/file_check.h"

static CPLHTTPResult *refuse_fetch(const char *url, CSLConstList options, GDALProgressFunc progress,
                                   void *progress_arg, CPLHTTPFetchWriteFunc write, void *write_arg,
                                   void *user)
{
    (void)url, (void)options, (void)progress, (void)progress_arg, (void)write, (void)write_arg, (void)user;
    CPLHTTPResult *r = CPLCalloc(1, sizeof *r); /* freed by GDAL */
    r->nStatus = 1;
    r->pszErrBuf = CPLStrdup("sylva reads the site's files without network access");
    return r;
}

void site_gdal_offline_begin(gdal_offline *g)
{
    GDALAllRegister();
    const char *old = CPLGetThreadLocalConfigOption("CPL_VSIL_CURL_ALLOWED_FILENAME", NULL);
    g->saved_curl = CPLStrdup(old ? old : "");
    CPLSetThreadLocalConfigOption("CPL_VSIL_CURL_ALLOWED_FILENAME", "sylva-network-is-off:");
    CPLHTTPPushFetchCallback(refuse_fetch, NULL);
    CPLPushErrorHandler(CPLQuietErrorHandler);
}

void site_gdal_offline_end(gdal_offline *g)
{
    CPLPopErrorHandler();
    CPLHTTPPopFetchCallback();
    CPLSetThreadLocalConfigOption("CPL_VSIL_CURL_ALLOWED_FILENAME", g->saved_curl[0] ? g->saved_curl : NULL);
    CPLFree(g->saved_curl);
    g->saved_curl = NULL;
}

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
    gdal_offline off;
    site_gdal_offline_begin(&off);
    GDALDatasetH ds = GDALOpenEx(path, GDAL_OF_RASTER | GDAL_OF_READONLY, NULL, NULL, NULL);
    int rc = ds ? read_dataset(ds, path, d, err)
                : err_set(err, "the DTM '%s' is not a raster GDAL reads (GeoTIFF, ESRI ASCII grid, "
                          "...), or it is damaged", path);
    if (ds) GDALClose(ds);
    site_gdal_offline_end(&off);
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
