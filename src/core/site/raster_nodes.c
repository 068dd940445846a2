/* raster_nodes.c — a raster's band read at the site grid's nodes (raster_nodes.h). */
#include "site/raster_nodes.h"

#include <math.h>
#include <stdlib.h>

#include "site/landcover_codes.h" /* landcover_node_coords: the nodes in the raster's CRS */
#include "util/memory_budget.h"

#define STRIP_BYTES ((size_t)64 << 20) /* the most of the raster held at once */

/* The window of the raster's cells [c0, c1] x [r0, r1] holding the nodes that fall on it. */
typedef struct cell_window {
    long c0, c1, r0, r1;
} cell_window;

/* Turns col[k], row[k] (a node's map point) into its cell's column and row (-1: off the
 * raster); returns the window that holds the rest and counts them in *covered. */
static cell_window cells_of_nodes(const double inv[6], int w, int h, double *col, double *row, size_t n,
                                  uint64_t *covered)
{
    cell_window win = {w, -1, h, -1};
    for (size_t k = 0; k < n; k++) {
        double c = inv[0] + inv[1] * col[k] + inv[2] * row[k], r = inv[3] + inv[4] * col[k] + inv[5] * row[k];
        int on = c >= 0 && r >= 0 && c < w && r < h;
        col[k] = on ? floor(c) : -1, row[k] = on ? floor(r) : -1;
        if (!on) continue;
        (*covered)++;
        long ci = (long)col[k], ri = (long)row[k];
        win.c0 = ci < win.c0 ? ci : win.c0, win.c1 = ci > win.c1 ? ci : win.c1;
        win.r0 = ri < win.r0 ? ri : win.r0, win.r1 = ri > win.r1 ? ri : win.r1;
    }
    return win;
}

/* 1 when v is the band's no-data value (as stored: a Float32 band's value compared in float). */
static int is_no_data(double v, int has_nodata, double nodata)
{
    if (!isfinite(v)) return 1;
    return has_nodata && (v == nodata || (float)v == (float)nodata);
}

/* Reads the window of band a strip of rows at a time, visiting each node on it. */
static int read_window(GDALRasterBandH band, const cell_window *win, const double *col, const double *row,
                       size_t n, const char *what, raster_node_fn visit, void *ctx, err_buf *err)
{
    size_t ww = (size_t)(win->c1 - win->c0 + 1), wh = (size_t)(win->r1 - win->r0 + 1);
    size_t rows = STRIP_BYTES / (ww * sizeof(double));
    rows = rows < 1 ? 1 : rows > wh ? wh : rows;
    if (memory_check(ww * rows * sizeof(double), what, err)) return -1;
    double *cells = malloc(ww * rows * sizeof *cells); /* freed below */
    if (!cells) return err_nomem(err, "out of memory reading %zu x %zu of %s", ww, rows, what);
    int has_nodata = 0;
    double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
    int rc = 0;
    for (long r0 = win->r0; !rc && r0 <= win->r1; r0 += (long)rows) {
        long got = win->r1 - r0 + 1 < (long)rows ? win->r1 - r0 + 1 : (long)rows;
        if (GDALRasterIO(band, GF_Read, (int)win->c0, (int)r0, (int)ww, (int)got, cells, (int)ww, (int)got,
                         GDT_Float64, 0, 0) != CE_None) {
            rc = err_set(err, "GDAL cannot read %s: %s", what, CPLGetLastErrorMsg());
            break;
        }
        for (size_t k = 0; k < n; k++) {
            if (col[k] < 0 || row[k] < r0 || row[k] >= r0 + got) continue;
            double v = cells[(size_t)((long)row[k] - r0) * ww + (size_t)((long)col[k] - win->c0)];
            visit(ctx, k, v, is_no_data(v, has_nodata, nodata));
        }
    }
    free(cells);
    return rc;
}

OGRSpatialReferenceH raster_nodes_srs(GDALDatasetH ds)
{
    OGRSpatialReferenceH srs = GDALGetSpatialRef(ds);
    if (!srs || !(srs = OSRClone(srs))) return NULL;
    OSRSetAxisMappingStrategy(srs, OAMS_TRADITIONAL_GIS_ORDER);
    return srs;
}

int raster_nodes_read(GDALDatasetH ds, const landcover_grid *g, const char *what, raster_node_fn visit, void *ctx,
                      uint64_t *covered, err_buf *err)
{
    *covered = 0;
    double gt[6], inv[6];
    if (GDALGetGeoTransform(ds, gt) != CE_None || !GDALInvGeoTransform(gt, inv))
        return err_set(err, "it has no georeferencing (no geotransform)");
    OGRSpatialReferenceH srs = raster_nodes_srs(ds);
    if (!srs) return err_set(err, "it names no CRS");
    double *col, *row; /* the nodes' map coordinates, then their cells; owned */
    int rc = landcover_node_coords(g, srs, &col, &row, err);
    OSRRelease(srs);
    if (rc) return -1;
    size_t n = (size_t)g->nx * g->ny;
    cell_window win =
        cells_of_nodes(inv, GDALGetRasterXSize(ds), GDALGetRasterYSize(ds), col, row, n, covered);
    if (*covered) rc = read_window(GDALGetRasterBand(ds, 1), &win, col, row, n, what, visit, ctx, err);
    free(col), free(row);
    return rc;
}
