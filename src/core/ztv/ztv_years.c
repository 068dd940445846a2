/* ztv_years.c — what a planting plan hides, year by year, from the maps of each year
 * (ztv_years.h). The maps are read back from the GeoTIFFs the study wrote, so each year's map is
 * exactly the one in its folder. */
#include "ztv/ztv_years.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal.h>

#include "io/atomic_file.h"
#include "ztv/ztv_raster.h"
#include "ztv/ztv_years_chart.h"

int ztv_years_visible_area(const char *summary_csv, const char *mode, double *km2, err_buf *err)
{
    FILE *f = fopen(summary_csv, "r");
    if (!f) return err_set(err, "%s: cannot read the map's summary", summary_csv);
    char line[512], quantity[128], row_mode[64];
    double value, sum = 0;
    int rows = 0;
    while (fgets(line, sizeof line, f))
        if (sscanf(line, "%127[^,],%63[^,],,%lf", quantity, row_mode, &value) == 3 && !strcmp(row_mode, mode) &&
            !strncmp(quantity, "area_visible_", 13) && strcmp(quantity, "area_visible_0"))
            sum += value, rows++;
    fclose(f);
    if (!rows) return err_set(err, "%s: no areas of the %s mode", summary_csv, mode);
    *km2 = sum;
    return 0;
}

/* The screened mode a folder's map was made in: `mode` when it has ztv_MODE.tif, else the mode a
 * scene with less in it falls back to (all without objects: vegetation; without plants, as before
 * the plan on open ground: bare earth). */
static const char *folder_mode(const char *dir, const char *mode)
{
    const char *const tried[] = {mode, "vegetation", "bare"};
    char path[4200];
    for (int k = 0; k < 3; k++) {
        snprintf(path, sizeof path, "%s/ztv_%s.tif", dir, tried[k]);
        FILE *f = fopen(path, "rb");
        if (f) {
            fclose(f);
            return tried[k];
        }
    }
    return mode;
}

void ztv_years_map_path(const char *dir, const char *mode, char *path, size_t n)
{
    snprintf(path, n, "%s/ztv_%s.tif", dir, folder_mode(dir, mode));
}

/* The map of one year: bands 1 (targets visible) and 3 (class) of ztv_MODE.tif. */
typedef struct year_map {
    GDALDatasetH ds;
    uint32_t nx, ny;
    float *visible, *cls; /* owned */
} year_map;

static void year_map_free(year_map *m)
{
    if (m->ds) GDALClose(m->ds);
    free(m->visible), free(m->cls);
}

static int year_map_read(const char *dir, const char *mode, year_map *m, err_buf *err)
{
    char path[4200];
    ztv_years_map_path(dir, mode, path, sizeof path);
    CPLPushErrorHandler(CPLQuietErrorHandler);
    m->ds = GDALOpen(path, GA_ReadOnly);
    CPLPopErrorHandler();
    if (!m->ds) return err_set(err, "%s: cannot read the map", path);
    m->nx = (uint32_t)GDALGetRasterXSize(m->ds), m->ny = (uint32_t)GDALGetRasterYSize(m->ds);
    size_t n = (size_t)m->nx * m->ny;
    m->visible = malloc(n * sizeof(float)), m->cls = malloc(n * sizeof(float));
    if (!m->visible || !m->cls) return err_nomem(err, "out of memory reading %s", path);
    if (GDALRasterIO(GDALGetRasterBand(m->ds, 1), GF_Read, 0, 0, (int)m->nx, (int)m->ny, m->visible, (int)m->nx,
                     (int)m->ny, GDT_Float32, 0, 0) != CE_None ||
        GDALRasterIO(GDALGetRasterBand(m->ds, 3), GF_Read, 0, 0, (int)m->nx, (int)m->ny, m->cls, (int)m->nx,
                     (int)m->ny, GDT_Float32, 0, 0) != CE_None)
        return err_set(err, "%s: cannot read its bands", path);
    return 0;
}

/* What the planting hides in a cell: -1 no viewpoint (either year), 0 nothing seen before, 1 still
 * all seen, 2 partly hidden, 3 hidden. *lost: the targets lost. */
static int cell_state(const year_map *before, const year_map *now, size_t k, float *lost)
{
    *lost = -1;
    if (before->cls[k] != ZTV_OPEN || now->cls[k] != ZTV_OPEN) return -1;
    float b = before->visible[k], a = now->visible[k];
    *lost = b > a ? b - a : 0;
    if (!(b > 0)) return 0;
    return a >= b ? 1 : a > 0 ? 2 : 3;
}

/* The hidden map's GeoTIFF on the year's grid and CRS. */
static int hidden_tif(const char *path, const year_map *before, const year_map *now, err_buf *err)
{
    size_t n = (size_t)now->nx * now->ny;
    float *bands = malloc(2 * n * sizeof *bands); /* owned here */
    if (!bands) return err_nomem(err, "out of memory for %s", path);
    for (size_t k = 0; k < n; k++) {
        float lost;
        cell_state(before, now, k, &lost);
        bands[k] = lost;
        bands[n + k] = ztv_class_on_ground((uint8_t)now->cls[k]) ? now->cls[k] : -1;
    }
    atomic_file af;
    if (atomic_file_open(&af, path, err)) {
        free(bands);
        return -1;
    }
    GDALDriverH tiff = GDALGetDriverByName("GTiff");
    char *options[] = {"COMPRESS=DEFLATE", NULL};
    CPLPushErrorHandler(CPLQuietErrorHandler);
    GDALDatasetH ds = tiff ? GDALCreate(tiff, af.tmp, (int)now->nx, (int)now->ny, 2, GDT_Float32, options) : NULL;
    int ok = ds != NULL;
    if (ds) {
        double gt[6];
        if (GDALGetGeoTransform(now->ds, gt) == CE_None) GDALSetGeoTransform(ds, gt);
        const char *wkt = GDALGetProjectionRef(now->ds);
        if (wkt && *wkt) GDALSetProjection(ds, wkt);
        for (int b = 1; b <= 2; b++) {
            GDALRasterBandH band = GDALGetRasterBand(ds, b);
            GDALSetRasterNoDataValue(band, -1);
            GDALSetDescription(band, b == 1 ? "targets hidden by the planting" : "cell class");
            ok = ok && GDALRasterIO(band, GF_Write, 0, 0, (int)now->nx, (int)now->ny, bands + (size_t)(b - 1) * n,
                                    (int)now->nx, (int)now->ny, GDT_Float32, 0, 0) == CE_None;
        }
        GDALClose(ds);
    }
    CPLPopErrorHandler();
    free(bands);
    if (!ok) {
        atomic_file_abort(&af);
        return err_set(err, "%s: GDAL cannot write it", path);
    }
    return atomic_file_commit(&af, err);
}

/* The year's maps against the one before the plan: the hidden map's GeoTIFF and areas (its page
 * was drawn with the year's map, ztv_map.h). */
static int year_products(const char *mode, const year_map *before, ztv_year_row *row, double cell_km2, err_buf *err)
{
    year_map now = {0};
    int rc = year_map_read(row->dir, mode, &now, err);
    if (!rc && (now.nx != before->nx || now.ny != before->ny))
        rc = err_set(err, "%s: its map is %u x %u cells, the map before the plan %u x %u", row->dir, now.nx, now.ny,
                     before->nx, before->ny);
    char path[4200];
    uint64_t hidden = 0, partly = 0;
    for (size_t k = 0; !rc && k < (size_t)now.nx * now.ny; k++) {
        float lost;
        int st = cell_state(before, &now, k, &lost);
        hidden += st == 3, partly += st == 2;
    }
    row->hidden_km2 = hidden * cell_km2, row->partly_km2 = partly * cell_km2;
    if (!rc) snprintf(path, sizeof path, "%s/ztv_hidden_by_planting.tif", row->dir), rc = hidden_tif(path, before, &now, err);
    year_map_free(&now);
    return rc;
}

static int write_table(const char *dir, const ztv_year_row *rows, uint32_t n, err_buf *err)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/visible_area.csv", dir);
    atomic_file af;
    FILE *f = atomic_file_open_stream(&af, path, err);
    if (!f) return -1;
    fprintf(f, "years_since_planting,visible_km2,hidden_by_planting_km2,partly_hidden_by_planting_km2\n");
    for (uint32_t r = 0; r < n; r++) {
        if (rows[r].year < 0) fprintf(f, "before,%.12g,0,0\n", rows[r].visible_km2);
        else fprintf(f, "%g,%.12g,%.12g,%.12g\n", rows[r].year, rows[r].visible_km2, rows[r].hidden_km2, rows[r].partly_km2);
    }
    return atomic_file_commit(&af, err);
}

static int write_chart(const char *dir, const ztv_year_row *rows, uint32_t n, err_buf *err)
{
    double year[256], visible[256], hidden[256], partly[256];
    uint32_t m = 0;
    for (uint32_t r = 1; r < n && m < 256; r++, m++)
        year[m] = rows[r].year, visible[m] = rows[r].visible_km2, hidden[m] = rows[r].hidden_km2,
        partly[m] = rows[r].partly_km2;
    ztv_years_areas a = {year, visible, hidden, partly, m, rows[0].visible_km2};
    char path[4200];
    snprintf(path, sizeof path, "%s/visible_area.png", dir);
    return ztv_years_chart_write(path, &a, err);
}

int ztv_years_write(const char *dir, const char *mode, ztv_year_row *rows, uint32_t n, err_buf *err)
{
    char summary[4200];
    for (uint32_t r = 0; r < n; r++) {
        snprintf(summary, sizeof summary, "%s/ztv_summary.csv", rows[r].dir);
        if (ztv_years_visible_area(summary, folder_mode(rows[r].dir, mode), &rows[r].visible_km2, err)) return -1;
    }
    year_map before = {0};
    int rc = year_map_read(rows[0].dir, mode, &before, err);
    double gt[6] = {0, 1, 0, 0, 0, -1};
    if (!rc) GDALGetGeoTransform(before.ds, gt);
    double cell_km2 = fabs(gt[1] * gt[5]) * 1e-6;
    for (uint32_t r = 1; r < n && !rc; r++) rc = year_products(mode, &before, &rows[r], cell_km2, err);
    year_map_free(&before);
    if (!rc) rc = write_table(dir, rows, n, err);
    if (!rc) rc = write_chart(dir, rows, n, err);
    return rc;
}
