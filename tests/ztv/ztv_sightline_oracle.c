/* ztv_sightline_oracle.c — an exact line of sight, independent of sylva's tracer, against which
 * a bare-earth ZTV written by `sylva ztv` is compared cell by cell.
 *
 *   ztv_sightline_oracle ZTV.tif DTM.tif EYE CURVE X Y H [X Y H ...]
 *
 * DTM.tif holds the heights at the ZTV's cell centres (its pixels are the cells); the ground is
 * the surface sylva draws over those nodes, two triangles per cell split along the diagonal from
 * its south-west to its north-east node (docs/sites.md). Target t stands H metres above the node
 * at local (X, Y) (the DTM's footprint centred on the origin, as a scene without a site places
 * it); a cell's observer stands EYE metres above its node. The sightline between them sags below
 * the straight segment by CURVE s (S - s) at horizontal distance s of S (CURVE = (1 - k) / 2R;
 * 0 on a flat Earth), followed here by chords of at most CHORD_M metres (they stray at most
 * CURVE CHORD_M^2 / 4 from it: 0.2 mm on the Earth). Each chord is tested in double precision
 * against every triangle of the cells it passes over: no BVH, no single precision, no tolerance
 * but the chord's.
 *
 * Prints the cell-targets on which the two agree, those only sylva sees and those only the
 * oracle sees; exit 0 when they agree on at least AGREEMENT_MIN of them, 1 when not, 2 on bad
 * usage or an unreadable file. sylva's curved sightlines are chords that stray up to 5 cm
 * (ZTV_SIGHT_SAG) above the curve, so a sightline grazing the ground that closely may differ.
 */
#include <gdal.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sightline_exact.h"
#include "ztv/ztv_raster.h"

#define AGREEMENT_MIN 0.999 /* share of the cell-targets on which sylva and the oracle agree */
static float *read_band(const char *path, int b, int *nx, int *ny, double gt[6])
{
    GDALDatasetH ds = GDALOpen(path, GA_ReadOnly);
    float *v = NULL;
    if (!ds) return fprintf(stderr, "ztv_sightline_oracle: cannot open %s\n", path), NULL;
    *nx = GDALGetRasterXSize(ds), *ny = GDALGetRasterYSize(ds);
    if (b <= GDALGetRasterCount(ds) && GDALGetGeoTransform(ds, gt) == CE_None &&
        (v = malloc((size_t)*nx * *ny * sizeof *v)) &&
        GDALRasterIO(GDALGetRasterBand(ds, b), GF_Read, 0, 0, *nx, *ny, v, *nx, *ny, GDT_Float32, 0, 0) != CE_None)
        free(v), v = NULL;
    if (!v) fprintf(stderr, "ztv_sightline_oracle: cannot read band %d of %s\n", b, path);
    GDALClose(ds);
    return v;
}

int main(int argc, char **argv)
{
    if (argc < 8 || (argc - 5) % 3 || (argc - 5) / 3 > (int)ZTV_MAX_DEVELOPMENTS) {
        fprintf(stderr, "usage: ztv_sightline_oracle ZTV.tif DTM.tif EYE CURVE X Y H [X Y H ...] (at most %u "
                "targets)\n", ZTV_MAX_DEVELOPMENTS);
        return 2;
    }
    GDALAllRegister();
    int nx, ny, mx, my;
    double gt[6], zgt[6];
    float *z = read_band(argv[2], 1, &nx, &ny, gt), *seen = read_band(argv[1], 4, &mx, &my, zgt);
    if (!z || !seen) return 2;
    if (mx != nx || my != ny) return fprintf(stderr, "ztv_sightline_oracle: the ZTV is not on the DTM's pixels\n"), 2;
    dtm d = {nx, ny, gt[1], -gt[5], z};
    double eye = atof(argv[3]), curve = atof(argv[4]);
    int n_targets = (argc - 5) / 3;
    long pairs = 0, only_sylva = 0, only_oracle = 0;
    for (int t = 0; t < n_targets; t++) {
        /* local (0, 0) is the footprint's centre: node ((nx - 1) / 2, (ny - 1) / 2) */
        double ti = atof(argv[5 + 3 * t]) / d.dx + 0.5 * (nx - 1), tj = atof(argv[6 + 3 * t]) / d.dy + 0.5 * (ny - 1);
        int i0 = (int)lround(ti), j0 = (int)lround(tj);
        if (fabs(ti - i0) > 1e-9 || fabs(tj - j0) > 1e-9 || i0 < 0 || j0 < 0 || i0 >= nx || j0 >= ny)
            return fprintf(stderr, "ztv_sightline_oracle: target %d is not on a node of the DTM\n", t + 1), 2;
        double target[3] = {i0 * d.dx, j0 * d.dy, node_z(&d, i0, j0) + atof(argv[7 + 3 * t])};
        long s_only = 0, o_only = 0;
        for (int row = 0; row < ny; row++)
            for (int i = 0; i < nx; i++) {
                int j = ny - 1 - row;
                double o[3] = {i * d.dx, j * d.dy, node_z(&d, i, j) + eye};
                int oracle = sightline_clear(&d, o, target, curve);
                int sylva = (uint32_t)seen[(size_t)row * nx + i] >> t & 1u;
                s_only += sylva && !oracle, o_only += oracle && !sylva;
            }
        printf("target %d: %ld cells, sylva only %ld, oracle only %ld\n", t + 1, (long)nx * ny, s_only, o_only);
        pairs += (long)nx * ny, only_sylva += s_only, only_oracle += o_only;
    }
    double agree = (double)(pairs - only_sylva - only_oracle) / pairs;
    printf("exact sightlines: %ld cell-targets, agree %.4f %% (sylva only %ld, oracle only %ld)\n", pairs, 100 * agree,
           only_sylva, only_oracle);
    free(z), free(seen);
    if (agree < AGREEMENT_MIN) {
        printf("FAIL: sylva and the exact sightlines agree on %.4f %% of the cell-targets, below %.1f %%\n",
               100 * agree, 100 * AGREEMENT_MIN);
        return 1;
    }
    return 0;
}
