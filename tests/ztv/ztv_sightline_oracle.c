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

#include "ztv/ztv_raster.h"

#define AGREEMENT_MIN 0.999 /* share of the cell-targets on which sylva and the oracle agree */
#define CHORD_M 100.0       /* longest chord of a curved sightline, metres */

typedef struct dtm {
    int nx, ny;       /* nodes; node (i, j): i east, j north, height z[(ny - 1 - j) nx + i] */
    double dx, dy;
    const float *z;
} dtm;

static double node_z(const dtm *d, int i, int j)
{
    return d->z[(size_t)(d->ny - 1 - j) * d->nx + i];
}

/* 1 when the segment o + u e, u in (0, 1), crosses the triangle (a, b, c) (Moller-Trumbore). */
static int crosses(const double o[3], const double e[3], const double a[3], const double b[3], const double c[3])
{
    double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double p[3] = {e[1] * e2[2] - e[2] * e2[1], e[2] * e2[0] - e[0] * e2[2], e[0] * e2[1] - e[1] * e2[0]};
    double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (det == 0.0) return 0;
    double s[3] = {o[0] - a[0], o[1] - a[1], o[2] - a[2]};
    double u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
    if (u < 0 || u > 1) return 0;
    double q[3] = {s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]};
    double v = (e[0] * q[0] + e[1] * q[1] + e[2] * q[2]) / det;
    if (v < 0 || u + v > 1) return 0;
    double t = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
    return t > 1e-9 && t < 1 - 1e-9;
}

/* 1 when the segment from o along e crosses the ground of cell (i, j) (south-west node). */
static int crosses_cell(const dtm *d, int i, int j, const double o[3], const double e[3])
{
    if (i < 0 || j < 0 || i >= d->nx - 1 || j >= d->ny - 1) return 0;
    double sw[3] = {i * d->dx, j * d->dy, node_z(d, i, j)}, se[3] = {(i + 1) * d->dx, j * d->dy, node_z(d, i + 1, j)};
    double ne[3] = {(i + 1) * d->dx, (j + 1) * d->dy, node_z(d, i + 1, j + 1)};
    double nw[3] = {i * d->dx, (j + 1) * d->dy, node_z(d, i, j + 1)};
    return crosses(o, e, sw, se, ne) || crosses(o, e, sw, ne, nw);
}

/* 1 when the segment from a to b crosses the ground: every cell within one of a point of its
 * trace taken each quarter cell is tested. */
static int segment_blocked(const dtm *d, const double a[3], const double b[3])
{
    double e[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    int n = (int)(hypot(e[0], e[1]) / (0.25 * fmin(d->dx, d->dy))) + 2, last_i = INT32_MIN, last_j = INT32_MIN;
    for (int k = 0; k <= n; k++) {
        int i = (int)floor((a[0] + e[0] * k / n) / d->dx), j = (int)floor((a[1] + e[1] * k / n) / d->dy);
        if (i == last_i && j == last_j) continue;
        last_i = i, last_j = j;
        for (int dj = -1; dj <= 1; dj++)
            for (int di = -1; di <= 1; di++)
                if (crosses_cell(d, i + di, j + dj, a, e)) return 1;
    }
    return 0;
}

/* 1 when the sightline from eye o to target t is clear (coordinates from node (0, 0)). */
static int sightline_clear(const dtm *d, const double o[3], const double t[3], double curve)
{
    double span = hypot(t[0] - o[0], t[1] - o[1]);
    int chords = curve > 0 ? (int)ceil(span / CHORD_M) : 1;
    if (chords < 1) chords = 1;
    double a[3] = {o[0], o[1], o[2]};
    for (int k = 1; k <= chords; k++) {
        double u = (double)k / chords;
        double b[3] = {o[0] + u * (t[0] - o[0]), o[1] + u * (t[1] - o[1]),
                       o[2] + u * (t[2] - o[2]) - curve * span * span * u * (1 - u)};
        if (segment_blocked(d, a, b)) return 0;
        memcpy(a, b, sizeof a);
    }
    return 1;
}

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
