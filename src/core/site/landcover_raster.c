/* landcover_raster.c — a classified raster's codes at the site grid's nodes (the nearest cell's
 * class, read by site/raster_nodes.h), with the raster's category names (its .aux.xml, GDAL's
 * category names, or a name column of its attribute table). */
#include "site/landcover_codes.h"

#include <math.h>
#include <stdlib.h>

#include <gdal.h>

#include "site/gdal_offline.h"
#include "site/raster_nodes.h"

/* Each node's cell value into its code (a value beyond the codes, like no data, gives none). */
static void code_of_node(void *ctx, size_t k, double value, int no_data)
{
    landcover_codes *c = ctx;
    double v = nearbyint(value);
    if (!no_data && v >= (double)INT32_MIN + 1 && v <= (double)INT32_MAX) c->code[k] = (int32_t)v;
}

/* The names of the band's categories: GDAL's category names (a PAM .aux.xml's among them),
 * else a name column of its raster attribute table. */
static int read_names(GDALRasterBandH band, landcover_codes *c, err_buf *err)
{
    char **names = GDALGetRasterCategoryNames(band); /* owned by the band */
    for (int64_t v = 0; names && names[v]; v++)
        if (names[v][0] && landcover_codes_add_name(c, v, names[v], err)) return -1;
    GDALRasterAttributeTableH rat = c->n_names ? NULL : GDALGetDefaultRAT(band);
    int name_col = rat ? GDALRATGetColOfUsage(rat, GFU_Name) : -1;
    int value_col = rat ? GDALRATGetColOfUsage(rat, GFU_MinMax) : -1;
    for (int row = 0; name_col >= 0 && row < GDALRATGetRowCount(rat); row++) {
        const char *name = GDALRATGetValueAsString(rat, row, name_col);
        int64_t v = value_col >= 0 ? GDALRATGetValueAsInt(rat, row, value_col) : row;
        if (name && name[0] && landcover_codes_add_name(c, v, name, err)) return -1;
    }
    return 0;
}

static int sample_raster(GDALDatasetH ds, const landcover_grid *g, landcover_codes *c, err_buf *err)
{
    double gt[6], inv[6];
    if (GDALGetGeoTransform(ds, gt) != CE_None || !GDALInvGeoTransform(gt, inv))
        return err_set(err, "it has no georeferencing (no geotransform)");
    OGRSpatialReferenceH srs = raster_nodes_srs(ds);
    if (!srs) return err_set(err, "it names no CRS");
    int w = GDALGetRasterXSize(ds), h = GDALGetRasterYSize(ds);
    landcover_codes_centre(c, srs, gt[0] + 0.5 * w * gt[1] + 0.5 * h * gt[2],
                           gt[3] + 0.5 * w * gt[4] + 0.5 * h * gt[5]);
    OSRRelease(srs);
    size_t n = (size_t)g->nx * g->ny;
    if (!(c->code = malloc(n * sizeof *c->code))) return err_nomem(err, "out of memory for %zu nodes' classes", n);
    for (size_t k = 0; k < n; k++) c->code[k] = LANDCOVER_NO_CODE;
    if (raster_nodes_read(ds, g, "the land-cover map's cells under the site", code_of_node, c, &c->covered, err))
        return -1;
    return c->covered ? read_names(GDALGetRasterBand(ds, 1), c, err) : 0;
}

int landcover_raster_codes(const landcover_source *src, const landcover_grid *g, landcover_codes *c, err_buf *err)
{
    gdal_offline off;
    GDALDatasetH ds = gdal_offline_open(src->path, GDAL_OF_RASTER, &off);
    int rc = ds ? sample_raster(ds, g, c, err) : err_set(err, "it is not a raster GDAL reads");
    gdal_offline_close(ds, &off);
    return rc;
}
