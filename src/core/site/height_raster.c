/* height_raster.c — a raster of heights sampled at the site grid's nodes (height_raster.h). */
#include "site/height_raster.h"

#include <math.h>
#include <stdlib.h>

#include <gdal.h>

#include "site/gdal_offline.h"
#include "site/raster_nodes.h"
#include "util/memory_budget.h"

int height_raster_check(const char *path, err_buf *err)
{
    gdal_offline off;
    GDALDatasetH ds = gdal_offline_open(path, GDAL_OF_RASTER, &off);
    double gt[6];
    int rc = 0;
    if (!ds) rc = err_set(err, "it is not a raster GDAL reads (GeoTIFF, ERDAS Imagine, an ASCII grid, ...)");
    else if (GDALGetRasterCount(ds) < 1) rc = err_set(err, "it has no raster band");
    else if (GDALGetGeoTransform(ds, gt) != CE_None) rc = err_set(err, "it has no georeferencing (no geotransform)");
    else if (!GDALGetSpatialRef(ds))
        rc = err_set(err, "it names no CRS (a .prj or .aux.xml beside it, or the file's own)");
    gdal_offline_close(ds, &off);
    return rc;
}

/* Each node's cell value into the heights, NAN on no data. */
static void height_of_node(void *ctx, size_t k, double value, int no_data)
{
    float *h = ctx;
    h[k] = no_data ? NAN : (float)value;
}

int height_raster_read(const char *path, const landcover_grid *g, float *h, uint64_t *covered, err_buf *err)
{
    size_t n = (size_t)g->nx * g->ny;
    *covered = 0;
    if (n > INT32_MAX) return err_set(err, "the site grid has %zu nodes, more than a height raster is read onto", n);
    if (memory_check(n * (HEIGHT_RASTER_NODE_BYTES + sizeof(float)), "reading a height raster onto the site grid",
                     err))
        return -1;
    gdal_offline off;
    GDALDatasetH ds = gdal_offline_open(path, GDAL_OF_RASTER, &off);
    for (size_t k = 0; k < n; k++) h[k] = NAN;
    int rc = ds ? raster_nodes_read(ds, g, "the height raster's cells under the site", height_of_node, h, covered, err)
                : err_set(err, "it is not a raster GDAL reads");
    gdal_offline_close(ds, &off);
    return rc;
}
