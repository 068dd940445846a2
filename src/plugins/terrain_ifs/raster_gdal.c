/* raster_gdal.c — reading one band of a raster through GDAL's C API, quietly. */
#include "raster_gdal.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include <cpl_error.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include "sylva/plugin.h"

/* GDAL's last message on this thread, or a fallback when it left none. */
static const char *gdal_reason(const char *fallback)
{
    const char *m = CPLGetLastErrorMsg();
    return m && m[0] ? m : fallback;
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

int ifs_raster_open(const char *path, uint32_t band, const char *what, ifs_raster *r, ifs_err *err)
{
    memset(r, 0, sizeof *r);
    r->metres_per_unit = 1.0, r->scale = 1.0;
    if (!path || !path[0]) return ifs_fail(err, SYLVA_ERR_PARAM, "no %s file was named", what);
    /* GDAL's virtual file systems (/vsizip/, /vsicurl/, ...) are not files to check here */
    if (strncmp(path, "/vsi", 4) && access(path, R_OK))
        return ifs_fail(err, SYLVA_ERR_IO, "cannot read the %s '%s': %s", what, path,
                        strerror(errno));
    GDALAllRegister();
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
    int rc = SYLVA_OK;
    GDALDatasetH ds = GDALOpenEx(path, GDAL_OF_RASTER | GDAL_OF_READONLY, NULL, NULL, NULL);
    if (!ds) {
        rc = ifs_fail(err, SYLVA_ERR_IO,
                      "cannot read the %s '%s': %s; give a raster GDAL reads (GeoTIFF, ESRI ASCII "
                      "grid, PNG, ...)", what, path, gdal_reason("GDAL does not recognise it"));
        goto done;
    }
    r->dataset = ds;
    r->cols = (uint32_t)GDALGetRasterXSize(ds);
    r->rows = (uint32_t)GDALGetRasterYSize(ds);
    r->bands = (uint32_t)GDALGetRasterCount(ds);
    if (band < 1 || band > r->bands) {
        rc = ifs_fail(err, SYLVA_ERR_PARAM, "the %s '%s' has %u band%s; band %u does not exist",
                      what, path, r->bands, r->bands == 1 ? "" : "s", band);
        goto done;
    }
    GDALRasterBandH b = GDALGetRasterBand(ds, (int)band);
    if (!b) {
        rc = ifs_fail(err, SYLVA_ERR_IO, "cannot read band %u of the %s '%s': %s", band, what, path,
                      gdal_reason("GDAL gave no band"));
        goto done;
    }
    r->band = b;
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
    if (rc) ifs_raster_close(r);
    return rc;
}

void ifs_raster_close(ifs_raster *r)
{
    if (!r) return;
    if (r->dataset) {
        CPLPushErrorHandler(CPLQuietErrorHandler);
        GDALClose((GDALDatasetH)r->dataset);
        CPLPopErrorHandler();
    }
    r->dataset = NULL, r->band = NULL;
}

int ifs_raster_read_row(ifs_raster *r, uint32_t row, uint32_t col, uint32_t count, double *out,
                        const char *what, ifs_err *err)
{
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
    CPLErr e = GDALRasterIO((GDALRasterBandH)r->band, GF_Read, (int)col, (int)row, (int)count, 1,
                            out, (int)count, 1, GDT_Float64, 0, 0);
    int rc = SYLVA_OK;
    if (e != CE_None)
        rc = ifs_fail(err, SYLVA_ERR_IO, "cannot read row %u of the %s: %s", row, what,
                      gdal_reason("GDAL reported a read failure"));
    CPLPopErrorHandler();
    if (rc) return rc;
    for (uint32_t k = 0; k < count; k++) {
        double v = out[k];
        if (isnan(v) || (r->has_nodata && v == r->nodata)) out[k] = NAN;
        else out[k] = v * r->scale + r->offset;
    }
    return SYLVA_OK;
}
