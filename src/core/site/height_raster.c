/* height_raster.c — a raster of heights sampled at the site grid's nodes (height_raster.h). */
#include "site/height_raster.h"

#include <math.h>
#include <stdlib.h>

#include <gdal.h>

#include "site/gdal_offline.h"
#include "site/landcover_codes.h" /* landcover_node_coords: the nodes in the raster's CRS */
#include "util/memory_budget.h"

#define STRIP_BYTES ((size_t)64 << 20) /* the most of the raster held at once */

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

/* The cells [c0, c1] x [r0, r1] under the nodes that fall on the raster, and each node's cell:
 * its column into col[k] and row into row[k] (both -1 off the raster), replacing the map
 * coordinates the arrays held. */
typedef struct window {
    long c0, c1, r0, r1;
} window;

static window cells_under(const double inv[6], int w, int h, double *col, double *row, size_t n, uint64_t *covered)
{
    window win = {w, -1, h, -1};
    *covered = 0;
    for (size_t k = 0; k < n; k++) {
        double c = inv[0] + inv[1] * col[k] + inv[2] * row[k], r = inv[3] + inv[4] * col[k] + inv[5] * row[k];
        int on = c >= 0 && r >= 0 && c < w && r < h;
        col[k] = on ? floor(c) : -1, row[k] = on ? floor(r) : -1;
        if (!on) continue;
        (*covered)++;
        win.c0 = (long)col[k] < win.c0 ? (long)col[k] : win.c0, win.c1 = (long)col[k] > win.c1 ? (long)col[k] : win.c1;
        win.r0 = (long)row[k] < win.r0 ? (long)row[k] : win.r0, win.r1 = (long)row[k] > win.r1 ? (long)row[k] : win.r1;
    }
    return win;
}

/* 1 when v is the band's no-data value (as stored: a Float32 band's value compared in float). */
static int is_no_data(double v, int has_nodata, double nodata)
{
    if (!isfinite(v)) return 1;
    return has_nodata && (v == nodata || (float)v == (float)nodata);
}

/* Reads the window of band a strip of rows at a time, each node's value into h. */
static int read_window(GDALRasterBandH band, const window *win, const double *col, const double *row, float *h,
                       size_t n, err_buf *err)
{
    size_t ww = (size_t)(win->c1 - win->c0 + 1), wh = (size_t)(win->r1 - win->r0 + 1);
    size_t rows = STRIP_BYTES / (ww * sizeof(double));
    rows = rows < 1 ? 1 : rows > wh ? wh : rows;
    if (memory_check(ww * rows * sizeof(double), "the height raster's cells under the site", err)) return -1;
    double *cells = malloc(ww * rows * sizeof *cells); /* freed below */
    if (!cells) return err_nomem(err, "out of memory reading %zu x %zu cells of a height raster", ww, rows);
    int has_nodata = 0;
    double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
    int rc = 0;
    for (long r0 = win->r0; !rc && r0 <= win->r1; r0 += (long)rows) {
        long got = win->r1 - r0 + 1 < (long)rows ? win->r1 - r0 + 1 : (long)rows;
        if (GDALRasterIO(band, GF_Read, (int)win->c0, (int)r0, (int)ww, (int)got, cells, (int)ww, (int)got,
                         GDT_Float64, 0, 0) != CE_None) {
            rc = err_set(err, "GDAL cannot read its cells: %s", CPLGetLastErrorMsg());
            break;
        }
        for (size_t k = 0; k < n; k++) {
            if (col[k] < 0 || row[k] < r0 || row[k] >= r0 + got) continue;
            double v = cells[(size_t)((long)row[k] - r0) * ww + (size_t)((long)col[k] - win->c0)];
            h[k] = is_no_data(v, has_nodata, nodata) ? NAN : (float)v;
        }
    }
    free(cells);
    return rc;
}

/* The raster's spatial reference in GIS axis order (a clone the caller releases), or NULL. */
static OGRSpatialReferenceH gis_order_srs(GDALDatasetH ds)
{
    OGRSpatialReferenceH srs = GDALGetSpatialRef(ds);
    if (!srs || !(srs = OSRClone(srs))) return NULL;
    OSRSetAxisMappingStrategy(srs, OAMS_TRADITIONAL_GIS_ORDER);
    return srs;
}

static int sample(GDALDatasetH ds, const landcover_grid *g, float *h, uint64_t *covered, err_buf *err)
{
    double gt[6], inv[6];
    if (GDALGetGeoTransform(ds, gt) != CE_None || !GDALInvGeoTransform(gt, inv))
        return err_set(err, "it has no georeferencing (no geotransform)");
    OGRSpatialReferenceH srs = gis_order_srs(ds);
    if (!srs) return err_set(err, "it names no CRS");
    double *col, *row; /* the nodes' map coordinates, then their cells; owned */
    int rc = landcover_node_coords(g, srs, &col, &row, err);
    OSRRelease(srs);
    if (rc) return -1;
    size_t n = (size_t)g->nx * g->ny;
    for (size_t k = 0; k < n; k++) h[k] = NAN;
    window win = cells_under(inv, GDALGetRasterXSize(ds), GDALGetRasterYSize(ds), col, row, n, covered);
    if (*covered) rc = read_window(GDALGetRasterBand(ds, 1), &win, col, row, h, n, err);
    free(col), free(row);
    return rc;
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
    int rc = ds ? sample(ds, g, h, covered, err) : err_set(err, "it is not a raster GDAL reads");
    gdal_offline_close(ds, &off);
    return rc;
}
