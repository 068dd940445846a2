/* raster_gdal.c — reading one band of a raster through GDAL's C API, quietly and offline.
 *
 * GDAL can reach the network on its own: a local VRT may name "/vsicurl/http://..." sources,
 * and drivers such as WMS fetch over HTTP. Unless the path handed in is itself such a name
 * (the host passes those only when the user allowed them with --allow-gdal-virtual), every GDAL
 * call here runs with the network shut for the calling thread: /vsicurl/ (and the cloud file
 * systems built on it) sees only one impossible file name (CPL_VSIL_CURL_ALLOWED_FILENAME) and
 * every CPLHTTPFetch is answered by a callback that refuses it. */
#include "raster_gdal.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_http.h>
#include <cpl_string.h>
#include <gdal.h>
#include <gdalwarper.h>
#include <ogr_srs_api.h>

#include "ascii_grid.h"
#include "sylva/plugin.h"

/* GDAL's last message on this thread, or a fallback when it left none. */
static const char *gdal_reason(const char *fallback)
{
    const char *m = CPLGetLastErrorMsg();
    return m && m[0] ? m : fallback;
}

/* --- the network switch ----------------------------------------------------------------------- */

#define OFFLINE_FILENAME "sylva-network-is-off:"

/* 1 when path names something GDAL reads through its virtual file systems or a driver prefix
 * rather than a local file: "/vsi...", "scheme://...", "DRIVER:...". */
static int names_virtual_source(const char *path)
{
    if (!strncmp(path, "/vsi", 4)) return 1;
    size_t n = 0;
    while ((path[n] >= 'a' && path[n] <= 'z') || (path[n] >= 'A' && path[n] <= 'Z') ||
           (path[n] >= '0' && path[n] <= '9') || path[n] == '_' || path[n] == '+' ||
           path[n] == '-' || path[n] == '.')
        n++;
    return n >= 2 && path[n] == ':';
}

static CPLHTTPResult *refuse_http(const char *url, CSLConstList options, GDALProgressFunc progress,
                                  void *progress_arg, CPLHTTPFetchWriteFunc write, void *write_arg,
                                  void *user)
{
    (void)url, (void)options, (void)progress, (void)progress_arg, (void)write, (void)write_arg;
    (void)user;
    CPLHTTPResult *r = CPLCalloc(1, sizeof *r); /* freed by GDAL (CPLHTTPDestroyResult) */
    r->nStatus = 1;
    r->pszErrBuf = CPLStrdup("network access is off in sylva (see --allow-gdal-virtual)");
    return r;
}

/* The network switch around GDAL calls on this thread; off unless r->network is set. */
static void offline_begin(const ifs_raster *r, char **saved)
{
    *saved = NULL;
    if (r->network) return;
    const char *old = CPLGetThreadLocalConfigOption("CPL_VSIL_CURL_ALLOWED_FILENAME", NULL);
    *saved = CPLStrdup(old ? old : "");
    CPLSetThreadLocalConfigOption("CPL_VSIL_CURL_ALLOWED_FILENAME", OFFLINE_FILENAME);
    CPLHTTPPushFetchCallback(refuse_http, NULL);
}

static void offline_end(const ifs_raster *r, char **saved)
{
    if (r->network) return;
    CPLHTTPPopFetchCallback();
    CPLSetThreadLocalConfigOption("CPL_VSIL_CURL_ALLOWED_FILENAME", (*saved)[0] ? *saved : NULL);
    CPLFree(*saved);
    *saved = NULL;
}

static double integer_type_max(GDALDataType t)
{
    switch (t) {
    case GDT_Byte: return 255.0;
    case GDT_UInt16: return 65535.0;
    case GDT_Int16: return 32767.0;
    case GDT_UInt32: return 4294967295.0;
    case GDT_Int32: return 2147483647.0;
    default: return 0.0;
    }
}

/* The nodata value given to a warped raster whose file declares none: a value of the sample
 * type far outside any terrain's heights. */
static double no_data_fallback(GDALDataType t)
{
    switch (t) {
    case GDT_Byte: return 255.0;
    case GDT_UInt16: return 65535.0;
    case GDT_Int16: return -32768.0;
    case GDT_UInt32: return 4294967295.0;
    case GDT_Int32: return -2147483648.0;
    default: return -3.4028234663852886e38;
    }
}

/* The warped VRT of ds into target_wkt (bilinear), or ds itself when the systems agree; NULL
 * with err set when ds has no system or GDAL cannot warp it. */
static GDALDatasetH warp_to(GDALDatasetH ds, const char *target_wkt, const char *what,
                            const char *path, int *warped, plugin_err *err)
{
    *warped = 0;
    OGRSpatialReferenceH src = GDALGetSpatialRef(ds), dst = OSRNewSpatialReference(NULL);
    if (!dst || OSRImportFromWkt(dst, (char **)&(const char *){target_wkt}) != OGRERR_NONE) {
        OSRDestroySpatialReference(dst);
        plugin_fail(err, SYLVA_ERR_PARAM, "the site's coordinate system is not WKT that GDAL reads");
        return NULL;
    }
    if (!src) {
        OSRDestroySpatialReference(dst);
        plugin_fail(err, SYLVA_ERR_PARAM, "the %s '%s' has no coordinate system, so it cannot be "
                 "placed in the site's; give the file one (gdal_edit.py -a_srs) or leave the "
                 "site out", what, path);
        return NULL;
    }
    int same = OSRIsSame(src, dst);
    OSRDestroySpatialReference(dst);
    if (same) return ds;
    GDALWarpOptions *wo = GDALCreateWarpOptions();
    wo->nBandCount = 0; /* every band */
    wo->papszWarpOptions = CSLSetNameValue(wo->papszWarpOptions, "INIT_DEST", "NO_DATA");
    int bands = GDALGetRasterCount(ds);
    double fallback = no_data_fallback(GDALGetRasterDataType(GDALGetRasterBand(ds, 1)));
    wo->padfDstNoDataReal = CPLMalloc(sizeof(double) * (size_t)(bands > 0 ? bands : 1));
    for (int b = 0; b < bands; b++) {
        int ok = 0;
        double nd = GDALGetRasterNoDataValue(GDALGetRasterBand(ds, b + 1), &ok);
        wo->padfDstNoDataReal[b] = ok ? nd : fallback;
    }
    GDALDatasetH vrt = GDALAutoCreateWarpedVRTEx(ds, NULL, target_wkt, GRA_Bilinear, 0.0, wo, NULL);
    GDALDestroyWarpOptions(wo);
    if (!vrt) {
        plugin_fail(err, SYLVA_ERR_PARAM, "cannot warp the %s '%s' into the site's coordinate system: "
                 "%s", what, path, gdal_reason("GDAL gave no reason"));
        return NULL;
    }
    for (int b = 0; b < bands; b++) { /* the areas outside the file are nodata */
        GDALRasterBandH vb = GDALGetRasterBand(vrt, b + 1);
        int ok = 0;
        double nd = GDALGetRasterNoDataValue(GDALGetRasterBand(ds, b + 1), &ok);
        GDALSetRasterNoDataValue(vb, ok ? nd : fallback);
    }
    *warped = 1;
    return vrt;
}

int ifs_raster_open(const char *path, uint32_t band, const char *what, ifs_raster *r, plugin_err *err)
{
    return ifs_raster_open_in(path, band, what, NULL, r, err);
}

int ifs_raster_open_in(const char *path, uint32_t band, const char *what, const char *target_wkt,
                       ifs_raster *r, plugin_err *err)
{
    memset(r, 0, sizeof *r);
    r->metres_per_unit = 1.0, r->scale = 1.0;
    if (!path || !path[0]) return plugin_fail(err, SYLVA_ERR_PARAM, "no %s file was named", what);
    /* GDAL's virtual file systems (/vsizip/, /vsicurl/, ...) and connection strings are not
     * files to check here; the host lets them through only when the user allowed them */
    r->network = names_virtual_source(path);
    if (!r->network) {
        struct stat st;
        if (stat(path, &st) || access(path, R_OK))
            return plugin_fail(err, SYLVA_ERR_IO, "cannot read the %s '%s': %s", what, path,
                            strerror(errno));
        if (!S_ISREG(st.st_mode)) /* a FIFO would block the open, a device never end */
            return plugin_fail(err, SYLVA_ERR_IO, "cannot read the %s '%s': it is %s, not a regular "
                            "file", what, path, S_ISDIR(st.st_mode)    ? "a folder"
                                                : S_ISFIFO(st.st_mode) ? "a FIFO (named pipe)"
                                                : S_ISCHR(st.st_mode)  ? "a character device"
                                                                       : "a special file");
        int rc = ifs_ascii_grid_check(path, what, err);
        if (rc) return rc;
    }
    GDALAllRegister();
    char *saved;
    offline_begin(r, &saved);
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
    int rc = SYLVA_OK;
    GDALDatasetH ds = GDALOpenEx(path, GDAL_OF_RASTER | GDAL_OF_READONLY, NULL, NULL, NULL);
    if (!ds) {
        /* GDAL's reasons for refusing a file can quote its first bytes, which may belong to any
         * file a scene names; the sentence says what is wrong without them */
        rc = plugin_fail(err, SYLVA_ERR_IO,
                      "cannot read the %s '%s': GDAL does not recognise it as a raster, or it is "
                      "damaged; give a raster GDAL reads (GeoTIFF, ESRI ASCII grid, PNG, ...)",
                      what, path);
        goto done;
    }
    r->dataset = ds;
    if (target_wkt) {
        GDALDatasetH v = warp_to(ds, target_wkt, what, path, &r->warped, err);
        if (!v) {
            rc = err->msg[0] ? SYLVA_ERR_PARAM : SYLVA_ERR_IO;
            goto done;
        }
        if (r->warped) r->source = ds, r->dataset = ds = v;
    }
    r->cols = (uint32_t)GDALGetRasterXSize(ds);
    r->rows = (uint32_t)GDALGetRasterYSize(ds);
    r->bands = (uint32_t)GDALGetRasterCount(ds);
    if (band < 1 || band > r->bands) {
        rc = plugin_fail(err, SYLVA_ERR_PARAM, "the %s '%s' has %u band%s; band %u does not exist",
                      what, path, r->bands, r->bands == 1 ? "" : "s", band);
        goto done;
    }
    GDALRasterBandH b = GDALGetRasterBand(ds, (int)band);
    if (!b) {
        rc = plugin_fail(err, SYLVA_ERR_IO, "cannot read band %u of the %s '%s': %s", band, what, path,
                      gdal_reason("GDAL gave no band"));
        goto done;
    }
    r->band = b;
    int bw = 0, bh = 0;
    GDALGetBlockSize(b, &bw, &bh);
    r->block_rows = bh > 0 ? (uint32_t)bh : 1;
    r->cached_block = UINT32_MAX;
    snprintf(r->driver, sizeof r->driver, "%s", GDALGetDriverShortName(GDALGetDatasetDriver(ds)));
    GDALDataType type = GDALGetRasterDataType(b);
    snprintf(r->type_name, sizeof r->type_name, "%s", GDALGetDataTypeName(type));
    r->type_max = integer_type_max(type);
    r->has_transform = GDALGetGeoTransform(ds, r->transform) == CE_None;
    if (!r->has_transform) {
        double identity[6] = {0, 1, 0, 0, 0, 1};
        memcpy(r->transform, identity, sizeof identity);
    }
    OGRSpatialReferenceH srs = GDALGetSpatialRef(ds);
    if (srs) {
        if (OSRIsGeographic(srs)) r->crs = IFS_CRS_GEOGRAPHIC;
        else if (OSRIsProjected(srs)) {
            r->crs = IFS_CRS_PROJECTED;
            double u = OSRGetLinearUnits(srs, NULL);
            r->metres_per_unit = u > 0 && isfinite(u) ? u : 1.0;
        } else r->crs = IFS_CRS_OTHER;
    }
    int ok = 0;
    double nd = GDALGetRasterNoDataValue(b, &ok);
    r->has_nodata = ok && !isnan(nd);
    r->nodata = nd;
    double s = GDALGetRasterScale(b, &ok);
    if (ok && s != 0.0 && isfinite(s)) r->scale = s;
    double o = GDALGetRasterOffset(b, &ok);
    if (ok && isfinite(o)) r->offset = o;
    if (r->type_max == 0.0 && r->has_nodata && type == GDT_Float32) r->nodata = (float)r->nodata;
done:
    CPLPopErrorHandler();
    offline_end(r, &saved);
    if (rc) ifs_raster_close(r);
    return rc;
}

void ifs_raster_close(ifs_raster *r)
{
    if (!r) return;
    if (r->dataset) {
        char *saved;
        offline_begin(r, &saved);
        CPLPushErrorHandler(CPLQuietErrorHandler);
        GDALClose((GDALDatasetH)r->dataset);
        if (r->source) GDALClose((GDALDatasetH)r->source);
        CPLPopErrorHandler();
        offline_end(r, &saved);
    }
    r->dataset = NULL, r->source = NULL, r->band = NULL;
}

int ifs_raster_read_row(ifs_raster *r, uint32_t row, uint32_t col, uint32_t count, double *out,
                        const char *what, plugin_err *err)
{
    char *saved;
    offline_begin(r, &saved);
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
    uint32_t block = row / (r->block_rows ? r->block_rows : 1);
    if (block != r->cached_block) {
        if (r->cached_block != UINT32_MAX) GDALFlushRasterCache((GDALRasterBandH)r->band);
        r->cached_block = block;
    }
    CPLErr e = GDALRasterIO((GDALRasterBandH)r->band, GF_Read, (int)col, (int)row, (int)count, 1,
                            out, (int)count, 1, GDT_Float64, 0, 0);
    int rc = SYLVA_OK;
    if (e != CE_None)
        rc = plugin_fail(err, SYLVA_ERR_IO, "cannot read row %u of the %s: %s", row, what,
                      gdal_reason("GDAL reported a read failure"));
    CPLPopErrorHandler();
    offline_end(r, &saved);
    if (rc) return rc;
    for (uint32_t k = 0; k < count; k++) {
        double v = out[k];
        if (isnan(v) || (r->has_nodata && v == r->nodata)) out[k] = NAN;
        else out[k] = v * r->scale + r->offset;
    }
    return SYLVA_OK;
}
