/* landcover_raster.c — a classified raster sampled at the site grid's nodes: each node's map
 * coordinates in the raster's CRS, the cell holding them (the nearest class; classes are never
 * interpolated), read from the window covering every node that falls on the raster, a strip of
 * rows at a time so that a fine map under a large site never has to be held whole. The
 * raster's category names (its .aux.xml, GDAL's category names, or a name column of its
 * attribute table) come with the codes. */
#include "site/landcover_codes.h"

#include <math.h>
#include <stdlib.h>

#include <gdal.h>

#include "site/gdal_offline.h"
#include "util/memory_budget.h"

/* The window of the raster's cells [c0, c1] x [r0, r1] holding the nodes that fall on it. */
typedef struct cell_window {
    long c0, c1, r0, r1;
    int empty;
} cell_window;

/* The cell under map point (x, y), or -1 in *col when it lies off the raster. */
static void cell_of(const double inv[6], int w, int h, double x, double y, long *col, long *row)
{
    double c = inv[0] + inv[1] * x + inv[2] * y, r = inv[3] + inv[4] * x + inv[5] * y;
    *col = *row = -1;
    if (!(c >= 0 && r >= 0 && c < w && r < h)) return;
    *col = (long)c, *row = (long)r;
}

/* Turns x[k] into the node's column and y[k] into its row (-1: off the raster); returns the
 * window that holds the rest. */
static cell_window cells_of_nodes(const double inv[6], int w, int h, double *x, double *y, size_t n)
{
    cell_window win = {w, -1, h, -1, 1};
    for (size_t k = 0; k < n; k++) {
        long c, r;
        cell_of(inv, w, h, x[k], y[k], &c, &r);
        x[k] = (double)c, y[k] = (double)r;
        if (c < 0) continue;
        if (c < win.c0) win.c0 = c;
        if (c > win.c1) win.c1 = c;
        if (r < win.r0) win.r0 = r;
        if (r > win.r1) win.r1 = r;
        win.empty = 0;
    }
    return win;
}

#define STRIP_BYTES ((size_t)64 << 20) /* the most of the map held at once */

/* A strip of the window: rows [r0, r0 + rows) of its cells, ww a row, from column c0. */
typedef struct cell_strip {
    const int32_t *cells;
    long r0, rows, c0;
    size_t ww;
} cell_strip;

/* The codes of the nodes whose cells lie in the strip (col in x, row in y). */
static void sample_strip(const cell_strip *st, GDALRasterBandH band, const double *x, const double *y,
                         landcover_codes *c, size_t n)
{
    int has_nodata = 0;
    double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
    for (size_t k = 0; k < n; k++) {
        if (x[k] < 0 || y[k] < st->r0 || y[k] >= st->r0 + st->rows) continue;
        int32_t v = st->cells[(size_t)((long)y[k] - st->r0) * st->ww + (size_t)((long)x[k] - st->c0)];
        c->covered++;
        if (!(has_nodata && (double)v == nodata)) c->code[k] = v;
    }
}

/* Reads the window of band, a strip of rows at a time, into codes per node (col in x, row in y). */
static int sample_window(GDALRasterBandH band, const cell_window *win, const double *x, const double *y,
                         landcover_codes *c, size_t n, err_buf *err)
{
    size_t ww = (size_t)(win->c1 - win->c0 + 1), wh = (size_t)(win->r1 - win->r0 + 1);
    size_t rows = STRIP_BYTES / (ww * sizeof(int32_t));
    rows = rows < 1 ? 1 : rows > wh ? wh : rows;
    if (memory_check(ww * rows * sizeof(int32_t), "the land-cover map's cells under the site", err)) return -1;
    int32_t *cells = malloc(ww * rows * sizeof *cells); /* freed below */
    if (!cells) return err_nomem(err, "out of memory reading %zu x %zu cells of the land-cover map", ww, rows);
    for (size_t k = 0; k < n; k++) c->code[k] = LANDCOVER_NO_CODE;
    int rc = 0;
    for (long r = win->r0; !rc && r <= win->r1; r += (long)rows) {
        cell_strip st = {cells, r, win->r1 - r + 1 < (long)rows ? win->r1 - r + 1 : (long)rows, win->c0, ww};
        if (GDALRasterIO(band, GF_Read, (int)win->c0, (int)r, (int)ww, (int)st.rows, cells, (int)ww, (int)st.rows,
                         GDT_Int32, 0, 0) != CE_None)
            rc = err_set(err, "GDAL cannot read the land-cover map's cells: %s", CPLGetLastErrorMsg());
        else sample_strip(&st, band, x, y, c, n);
    }
    free(cells);
    return rc;
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

/* The raster's spatial reference in GIS axis order (a clone the caller releases), or NULL. */
static OGRSpatialReferenceH raster_srs(GDALDatasetH ds)
{
    OGRSpatialReferenceH srs = GDALGetSpatialRef(ds);
    if (!srs) return NULL;
    srs = OSRClone(srs);
    if (srs) OSRSetAxisMappingStrategy(srs, OAMS_TRADITIONAL_GIS_ORDER);
    return srs;
}

static int sample_raster(GDALDatasetH ds, const landcover_grid *g, landcover_codes *c, err_buf *err)
{
    double gt[6], inv[6];
    if (GDALGetGeoTransform(ds, gt) != CE_None || !GDALInvGeoTransform(gt, inv))
        return err_set(err, "it has no georeferencing (no geotransform)");
    OGRSpatialReferenceH srs = raster_srs(ds);
    if (!srs) return err_set(err, "it names no CRS");
    int w = GDALGetRasterXSize(ds), h = GDALGetRasterYSize(ds);
    landcover_codes_centre(c, srs, gt[0] + 0.5 * w * gt[1] + 0.5 * h * gt[2],
                           gt[3] + 0.5 * w * gt[4] + 0.5 * h * gt[5]);
    double *x, *y;
    int rc = landcover_node_coords(g, srs, &x, &y, err);
    OSRRelease(srs);
    if (rc) return -1;
    size_t n = (size_t)g->nx * g->ny;
    cell_window win = cells_of_nodes(inv, w, h, x, y, n);
    GDALRasterBandH band = GDALGetRasterBand(ds, 1);
    if (!(c->code = malloc(n * sizeof *c->code))) rc = err_nomem(err, "out of memory for %zu nodes' classes", n);
    else if (win.empty) for (size_t k = 0; k < n; k++) c->code[k] = LANDCOVER_NO_CODE;
    else rc = sample_window(band, &win, x, y, c, n, err) || read_names(band, c, err) ? -1 : 0;
    free(x), free(y);
    return rc;
}

int landcover_raster_codes(const landcover_source *src, const landcover_grid *g, landcover_codes *c, err_buf *err)
{
    gdal_offline off;
    GDALDatasetH ds = gdal_offline_open(src->path, GDAL_OF_RASTER, &off);
    int rc = ds ? sample_raster(ds, g, c, err) : err_set(err, "it is not a raster GDAL reads");
    gdal_offline_close(ds, &off);
    return rc;
}
