/* canopy_ground.c — the ground under a canopy height model, made for the canopy screening check
 * (canopy_check.sh): a synthetic terrain model on the CHM's own grid and CRS, and the surface
 * model a practitioner would run gdal_viewshed on (the terrain plus the canopy), and the cells
 * where masts stand.
 *
 *   canopy_ground CHM.tif DIR MASTS
 *
 * writes DIR/dtm.tif (Float32: 800 m, rising 5 % to the east, and a 2 m swell every 80 m to the
 * north: z = 800 + 0.05 u + 2 sin(2 pi v / 80), u and v metres east and north of the CHM's
 * centre) and DIR/dsm.tif (Float32: dtm + CHM, the CHM's no-data cells and its values below 0
 * taken as 0), both with the CHM's geotransform and CRS. Then prints MASTS lines "E N C": the map
 * coordinates of the centre of an open cell (CHM below OPEN_BELOW, or no data) and its CHM value
 * C (0 for no data), for mast m the open cell nearest to the m-th point of the layout
 * (nx/4, ny/4), (3nx/4, ny/2), (nx/2, 3ny/4), (nx/4, 3ny/4), (3nx/4, ny/4) (columns and rows).
 * Exit 0, 1 when no open cell is found, 2 on bad usage or a file it cannot read or write. */
#include <gdal.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "ztv_band.h"

#define TOOL "canopy_ground"
#define OPEN_BELOW 0.1 /* metres: a mast stands where the canopy is lower */
#define MAX_MASTS 5

/* The CHM's height at cell k, NAN for no data. */
static double chm_at(const float *chm, const raster *r, size_t k)
{
    double v = chm[k];
    if (!isfinite(v) || v < -1e30 || (r->has_nodata && (float)v == (float)r->nodata)) return NAN;
    return v;
}

/* Writes values (r's grid) as a Float32 GeoTIFF at path with the CRS of wkt; 0 or -1. */
static int write_tif(const char *path, const raster *r, const char *wkt, float *values)
{
    GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path, r->nx, r->ny, 1, GDT_Float32, NULL);
    if (!ds) return -1;
    GDALSetGeoTransform(ds, (double *)r->gt);
    GDALSetProjection(ds, wkt);
    int rc = GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, r->nx, r->ny, values, r->nx, r->ny, GDT_Float32, 0,
                          0) == CE_None ? 0 : -1;
    GDALClose(ds);
    return rc;
}

/* The synthetic ground at cell (i, j). */
static float ground(const raster *r, int i, int j)
{
    double u = (i + 0.5 - 0.5 * r->nx) * r->gt[1], v = -(j + 0.5 - 0.5 * r->ny) * r->gt[5];
    return (float)(800.0 + 0.05 * u + 2.0 * sin(2.0 * M_PI * v / 80.0));
}

/* The open cell nearest (ci, cj) into *k; -1 when there is none. */
static int nearest_open(const float *chm, const raster *r, int ci, int cj, size_t *k)
{
    double best = INFINITY;
    for (int j = 0; j < r->ny; j++)
        for (int i = 0; i < r->nx; i++) {
            double h = chm_at(chm, r, (size_t)j * r->nx + i), d = hypot(i - ci, j - cj);
            if ((isnan(h) || h < OPEN_BELOW) && d < best) best = d, *k = (size_t)j * r->nx + i;
        }
    return isfinite(best) ? 0 : -1;
}

int main(int argc, char **argv)
{
    int masts = argc == 4 ? atoi(argv[3]) : 0;
    if (masts < 1 || masts > MAX_MASTS) {
        fprintf(stderr, "usage: canopy_ground CHM.tif DIR MASTS (1 to %d)\n", MAX_MASTS);
        return 2;
    }
    GDALAllRegister();
    raster r;
    float *chm = read_band(TOOL, argv[1], 1, &r);
    GDALDatasetH src = GDALOpen(argv[1], GA_ReadOnly);
    size_t n = (size_t)r.nx * r.ny;
    float *dtm = malloc(n * sizeof *dtm), *dsm = malloc(n * sizeof *dsm);
    if (!chm || !src || !dtm || !dsm) return 2;
    for (int j = 0; j < r.ny; j++)
        for (int i = 0; i < r.nx; i++) {
            size_t k = (size_t)j * r.nx + i;
            double h = chm_at(chm, &r, k);
            dtm[k] = ground(&r, i, j);
            dsm[k] = dtm[k] + (float)(isnan(h) || h < 0 ? 0.0 : h);
        }
    char dtm_path[4096], dsm_path[4096];
    snprintf(dtm_path, sizeof dtm_path, "%s/dtm.tif", argv[2]);
    snprintf(dsm_path, sizeof dsm_path, "%s/dsm.tif", argv[2]);
    if (write_tif(dtm_path, &r, GDALGetProjectionRef(src), dtm) || write_tif(dsm_path, &r, GDALGetProjectionRef(src), dsm)) {
        fprintf(stderr, "%s: cannot write %s and %s\n", TOOL, dtm_path, dsm_path);
        return 2;
    }
    const int layout[MAX_MASTS][2] = {{1, 1}, {3, 2}, {2, 3}, {1, 3}, {3, 1}}; /* quarters of nx, ny */
    for (int m = 0; m < masts; m++) {
        size_t k = 0;
        if (nearest_open(chm, &r, layout[m][0] * r.nx / 4, layout[m][1] * r.ny / 4, &k)) {
            fprintf(stderr, "%s: %s has no open cell for a mast\n", TOOL, argv[1]);
            return 1;
        }
        int i = (int)(k % r.nx), j = (int)(k / r.nx);
        double h = chm_at(chm, &r, k);
        printf("%.6f %.6f %.4f\n", r.gt[0] + (i + 0.5) * r.gt[1], r.gt[3] + (j + 0.5) * r.gt[5], isnan(h) ? 0.0 : h);
    }
    GDALClose(src);
    free(chm), free(dtm), free(dsm);
    return 0;
}
