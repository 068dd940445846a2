/* ztv_geotiff.c — the GeoTIFF writer: GDAL creates the file on a temporary that atomic_file
 * made (so no planted name is ever followed at creation), writes row blocks through
 * GDALDatasetRasterIO, and the temporary is checked to still be the file made before it is
 * renamed. Strips are STRIP_ROWS rows high, DEFLATE at level 1 without a predictor (the bands
 * hold few distinct values, which it packs as small without the predictor's cost); the rows are
 * gathered here into whole strips, each written and flushed out of GDAL's cache at once, so that
 * the file is the same bytes whatever the blocks it is given and memory stays that of a strip.
 * GDAL stays quiet (its messages go into err) and writes no .aux.xml sidecar. */
#include "ztv/ztv_geotiff.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal.h>

#include "io/atomic_file.h"

#define STRIP_ROWS 16 /* rows a strip */

struct ztv_geotiff {
    const ztv_info *info;   /* borrowed */
    atomic_file file;       /* the temporary, open until commit or free */
    GDALDatasetH ds;        /* open until finish; closed by ztv_geotiff_free otherwise */
    uint32_t bands;
    uint32_t rows_written;  /* rows [0, rows_written) were given: in the file or pending */
    float *pending;         /* the strip being gathered: bands planes of STRIP_ROWS rows; owned */
    uint32_t pending_rows;  /* rows of it gathered, the last of those given */
};

/* GDAL's state while it works on our dataset: its messages caught, no PAM sidecar; the
 * thread's own setting comes back after (saved is CPLFree'd by gdal_leave). */
static char *gdal_enter(void)
{
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
    const char *old = CPLGetThreadLocalConfigOption("GDAL_PAM_ENABLED", NULL);
    char *saved = old ? CPLStrdup(old) : NULL;
    CPLSetThreadLocalConfigOption("GDAL_PAM_ENABLED", "NO");
    return saved;
}

static void gdal_leave(char *saved)
{
    CPLSetThreadLocalConfigOption("GDAL_PAM_ENABLED", saved);
    CPLFree(saved);
    CPLPopErrorHandler();
}

static const char *gdal_why(void)
{
    const char *why = CPLGetLastErrorMsg();
    return why && *why ? why : "GDAL gave no reason";
}

ztv_geotiff *ztv_geotiff_open(const char *path, const ztv_info *info, uint32_t bands,
                              const char *const *descriptions, err_buf *err)
{
    if (bands < 1 || bands > ZTV_GEOTIFF_MAX_BANDS) {
        err_set(err, "%s: a visibility GeoTIFF has 1 to %u bands, not %u", path, ZTV_GEOTIFF_MAX_BANDS, bands);
        return NULL;
    }
    if (info->grid.nx > INT32_MAX || info->grid.ny > INT32_MAX) {
        err_fail(err, ERR_LIMIT, "%s: a grid of %u x %u cells is beyond what GDAL addresses", path,
                 info->grid.nx, info->grid.ny);
        return NULL;
    }
    ztv_geotiff *g = calloc(1, sizeof *g); /* owned by the caller: ztv_geotiff_free */
    if (!g) {
        err_nomem(err, "out of memory for the GeoTIFF writer of %s", path);
        return NULL;
    }
    g->info = info;
    g->bands = bands;
    g->pending = malloc((size_t)bands * STRIP_ROWS * info->grid.nx * sizeof *g->pending); /* freed with g */
    if (!g->pending) {
        err_nomem(err, "out of memory for a strip of %s", path);
        free(g);
        return NULL;
    }
    if (atomic_file_open(&g->file, path, err)) {
        free(g->pending);
        free(g);
        return NULL;
    }
    GDALAllRegister();
    char *saved = gdal_enter();
    int rc = 0;
    GDALDriverH driver = GDALGetDriverByName("GTiff");
    char strip[32];
    snprintf(strip, sizeof strip, "BLOCKYSIZE=%d", STRIP_ROWS);
    const char *const options[] = {"COMPRESS=DEFLATE", "ZLEVEL=1", "PREDICTOR=1", "INTERLEAVE=PIXEL",
                                   strip, "BIGTIFF=IF_SAFER", NULL};
    if (!driver) rc = err_fail(err, ERR_INTERNAL, "%s: GDAL has no GeoTIFF driver", path);
    if (!rc) {
        g->ds = GDALCreate(driver, g->file.tmp, (int)info->grid.nx, (int)info->grid.ny, (int)bands,
                           GDT_Float32, (char **)options);
        if (!g->ds) rc = err_fail(err, ERR_OUTPUT, "%s: GDAL cannot create the GeoTIFF: %s", path, gdal_why());
    }
    const ztv_grid *grid = &info->grid;
    double transform[6] = {info->origin[0] + grid->x0 - 0.5 * grid->cell, grid->cell, 0,
                           info->origin[1] + grid->y0 + 0.5 * grid->cell, 0, -grid->cell};
    if (!rc && GDALSetGeoTransform(g->ds, transform) != CE_None)
        rc = err_fail(err, ERR_OUTPUT, "%s: GDAL cannot set the geotransform: %s", path, gdal_why());
    if (!rc && info->crs_wkt && GDALSetProjection(g->ds, info->crs_wkt) != CE_None)
        rc = err_fail(err, ERR_INPUT, "%s: GDAL does not accept the site's CRS: %s", path, gdal_why());
    for (uint32_t b = 0; !rc && b < bands; b++) {
        GDALRasterBandH band = GDALGetRasterBand(g->ds, (int)b + 1);
        GDALSetDescription(band, descriptions[b]);
        if (GDALSetRasterNoDataValue(band, ZTV_GEOTIFF_NODATA) != CE_None)
            rc = err_fail(err, ERR_OUTPUT, "%s: GDAL cannot set the nodata value: %s", path, gdal_why());
    }
    gdal_leave(saved);
    if (rc) {
        ztv_geotiff_free(g);
        return NULL;
    }
    return g;
}

/* Writes the strip gathered (a whole one, or the grid's last) and drops it from GDAL's cache. */
static int write_strip(ztv_geotiff *g, err_buf *err)
{
    uint32_t j0 = g->rows_written - g->pending_rows, nx = g->info->grid.nx;
    char *saved = gdal_enter();
    CPLErr e = GDALDatasetRasterIO(g->ds, GF_Write, 0, (int)j0, (int)nx, (int)g->pending_rows, g->pending, (int)nx,
                                   (int)g->pending_rows, GDT_Float32, (int)g->bands, NULL, 0, 0,
                                   (GSpacing)STRIP_ROWS * nx * sizeof *g->pending);
    if (e == CE_None) GDALFlushCache(g->ds);
    int rc = e == CE_None && CPLGetLastErrorType() < CE_Failure
                 ? 0
                 : err_fail(err, ERR_OUTPUT, "%s: GDAL cannot write rows %u to %u: %s", g->file.path, j0,
                            j0 + g->pending_rows, gdal_why());
    gdal_leave(saved);
    g->pending_rows = 0;
    return rc;
}

int ztv_geotiff_rows(ztv_geotiff *g, uint32_t j0, uint32_t rows, const float *values, err_buf *err)
{
    if (!g->ds || j0 != g->rows_written || rows == 0 || rows > g->info->grid.ny - j0)
        return err_fail(err, ERR_INTERNAL, "%s: rows %u to %u cannot follow the %u rows written",
                        g->file.path, j0, j0 + rows, g->rows_written);
    size_t nx = g->info->grid.nx, plane = (size_t)STRIP_ROWS * nx;
    for (uint32_t r = 0; r < rows; r++) {
        for (uint32_t b = 0; b < g->bands; b++)
            memcpy(g->pending + b * plane + g->pending_rows * nx, values + ((size_t)b * rows + r) * nx,
                   nx * sizeof *values);
        g->pending_rows++, g->rows_written++;
        if ((g->pending_rows == STRIP_ROWS || g->rows_written == g->info->grid.ny) && write_strip(g, err)) return -1;
    }
    return 0;
}

int ztv_geotiff_finish(ztv_geotiff *g, err_buf *err)
{
    if (!g->ds) return err_fail(err, ERR_INTERNAL, "%s: the GeoTIFF is not open", g->file.path);
    if (g->rows_written != g->info->grid.ny)
        return err_fail(err, ERR_INTERNAL, "%s: only %u of %u rows were written", g->file.path,
                        g->rows_written, g->info->grid.ny);
    char *saved = gdal_enter();
    GDALFlushCache(g->ds);
    int failed = CPLGetLastErrorType() >= CE_Failure;
    GDALClose(g->ds);
    failed |= CPLGetLastErrorType() >= CE_Failure;
    g->ds = NULL;
    int rc = failed ? err_fail(err, ERR_OUTPUT, "%s: GDAL cannot finish the GeoTIFF: %s", g->file.path,
                               gdal_why())
                    : 0;
    gdal_leave(saved);
    if (rc) return rc;
    /* GDAL opened the temporary by name: it must still be the file atomic_file created */
    struct stat ours, there;
    if (fstat(g->file.fd, &ours) != 0 || lstat(g->file.tmp, &there) != 0 || !S_ISREG(there.st_mode) ||
        ours.st_ino != there.st_ino || ours.st_dev != there.st_dev)
        return err_fail(err, ERR_OUTPUT, "%s: its temporary %s was replaced while it was written",
                        g->file.path, g->file.tmp);
    return 0;
}

int ztv_geotiff_commit(ztv_geotiff *g, err_buf *err)
{
    if (g->ds) return err_fail(err, ERR_INTERNAL, "%s: the GeoTIFF is not finished", g->file.path);
    return atomic_file_commit(&g->file, err);
}

void ztv_geotiff_free(ztv_geotiff *g)
{
    if (!g) return;
    if (g->ds) {
        char *saved = gdal_enter();
        GDALClose(g->ds);
        gdal_leave(saved);
    }
    atomic_file_abort(&g->file);
    free(g->pending);
    free(g);
}
