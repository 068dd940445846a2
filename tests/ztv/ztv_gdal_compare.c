/* ztv_gdal_compare.c — compares a bare-earth ZTV written by `sylva ztv` with gdal_viewshed's
 * maps of the same targets, cell by cell, and prints the figures of the agreement.
 *
 *   ztv_gdal_compare ZTV.tif DTM.tif GDAL_1.tif [GDAL_2.tif ...]
 *
 * ZTV.tif is sylva's map (band 3 the cell class, band 4 the developments seen, one bit each);
 * target t of the scene is development t, alone, and GDAL_t.tif is gdal_viewshed run from that
 * target over DTM.tif (the raster gdal_viewshed read: it has the ZTV's cells as pixels). By
 * reciprocity, gdal_viewshed's observer at the target (-oz its height above ground) seeing a
 * cell's ground plus -tz (the ZTV's observer height) is the ZTV's observer seeing the target.
 *
 * Checks, failing (exit 1) when one does not hold:
 *  - the rasters line up: same size and cell, and the ZTV's origin is the DTM's, either in map
 *    coordinates (a site) or shifted by the centre of the DTM's footprint (a scene in local
 *    metres, whose terrain stands centred on the origin);
 *  - every cell is a viewpoint (bare earth), and band 1 (targets seen) counts band 4's bits;
 *  - over all cells and targets, sylva and gdal_viewshed agree on at least 99 % of the pairs;
 *  - the pairs that differ lie along visibility edges: at least 95 % of them lie within
 *    EDGE_CELLS cells (in x and in y) of a cell that either map of that target gives the other
 *    visibility: the differences are slivers along an edge and islands a few cells across that
 *    one tool sees and the other does not, not whole regions (the share within 2 cells of an
 *    edge of gdal_viewshed's map alone is printed too: in canyon country it is lower, as
 *    gdal_viewshed hides whole small islands of cells that exact sightlines see). gdal_viewshed is not an exact line of sight (Wang, Robinson and
 *    White 2000: each cell's horizon height is interpolated from the two cells before it on the
 *    way out from the observer, so a horizon that turns sideways is smeared over a cell or two),
 *    and sylva's ground is two triangles per cell where gdal_viewshed sees heights at centres:
 *    the two may differ where visibility changes, not inside a visible or hidden region.
 * Prints, per target and in all: cells, agreement, the pairs only sylva sees and only
 * gdal_viewshed sees, and how many of the differing pairs lie within 1 and within 2 cells of an
 * edge. Exit 0 when every check holds, 1 when one fails, 2 on bad usage or an unreadable file.
 */
#include <gdal.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "ztv/ztv_raster.h"
#include "ztv_band.h"

#define TOOL "ztv_gdal_compare"

#define AGREEMENT_MIN 0.99 /* share of (cell, target) pairs on which the two agree */
#define EDGE_SHARE_MIN 0.95 /* share of the differing pairs that lie along an edge */
#define EDGE_CELLS 2        /* "along an edge": within this many cells of one, in x and in y */

/* 1 when the ZTV's cells are the DTM's pixels; prints how they line up. */
static int lined_up(const raster *z, const raster *d)
{
    if (z->nx != d->nx || z->ny != d->ny) {
        printf("FAIL: the ZTV is %d x %d cells, the DTM %d x %d pixels\n", z->nx, z->ny, d->nx, d->ny);
        return 0;
    }
    const double tol = 1e-6 * fabs(d->gt[1]);
    if (fabs(z->gt[1] - d->gt[1]) > tol || fabs(z->gt[5] - d->gt[5]) > tol || z->gt[2] != 0 || z->gt[4] != 0) {
        printf("FAIL: the ZTV's cells are %g x %g m, the DTM's pixels %g x %g m\n", z->gt[1], -z->gt[5], d->gt[1],
               -d->gt[5]);
        return 0;
    }
    double cx = d->gt[0] + 0.5 * d->nx * d->gt[1], cy = d->gt[3] + 0.5 * d->ny * d->gt[5];
    if (fabs(z->gt[0] - d->gt[0]) <= tol && fabs(z->gt[3] - d->gt[3]) <= tol) {
        printf("grid: %d x %d cells of %g m, on the DTM's pixels in map coordinates\n", z->nx, z->ny, z->gt[1]);
        return 1;
    }
    if (fabs(z->gt[0] + cx - d->gt[0]) <= tol && fabs(z->gt[3] + cy - d->gt[3]) <= tol) {
        printf("grid: %d x %d cells of %g m, on the DTM's pixels (local metres, the footprint's centre "
               "(%.3f, %.3f) at the origin)\n", z->nx, z->ny, z->gt[1], cx, cy);
        return 1;
    }
    printf("FAIL: the ZTV's north-west corner (%.6f, %.6f) is neither the DTM's (%.6f, %.6f) nor that "
           "shifted by its centre (%.6f, %.6f)\n", z->gt[0], z->gt[3], d->gt[0], d->gt[3], cx, cy);
    return 0;
}

/* 1 when a cell within `reach` of (i, j) has the other visibility than (i, j) in gdal_viewshed's map
 * g, or (seen not NULL) in sylva's map of target t (bit t of seen). */
static int near_edge(const float *g, const float *seen, int t, int nx, int ny, int i, int j, int reach)
{
    size_t k = (size_t)j * nx + i;
    int here_g = g[k] > 0, here_s = seen ? (uint32_t)seen[k] >> t & 1u : 0;
    for (int dj = -reach; dj <= reach; dj++)
        for (int di = -reach; di <= reach; di++) {
            int ii = i + di, jj = j + dj;
            if (ii < 0 || jj < 0 || ii >= nx || jj >= ny) continue;
            size_t q = (size_t)jj * nx + ii;
            if ((g[q] > 0) != here_g || (seen && (int)((uint32_t)seen[q] >> t & 1u) != here_s)) return 1;
        }
    return 0;
}

typedef struct tally {
    long pairs, differ, only_sylva, only_gdal, edge1, edge2, gdal_edge2, gdal_visible, sylva_visible;
} tally;

static void print_tally(const char *what, const tally *t)
{
    printf("%-8s %7ld cells  agree %7.3f %%  differ %5ld (sylva only %ld, gdal only %ld)  within 1 cell of "
           "an edge %5.1f %%, within 2 %5.1f %% (of gdal's edges %5.1f %%)  visible: sylva %ld, gdal %ld\n",
           what, t->pairs, 100.0 * (t->pairs - t->differ) / t->pairs, t->differ, t->only_sylva, t->only_gdal,
           t->differ ? 100.0 * t->edge1 / t->differ : 100.0, t->differ ? 100.0 * t->edge2 / t->differ : 100.0,
           t->differ ? 100.0 * t->gdal_edge2 / t->differ : 100.0, t->sylva_visible, t->gdal_visible);
}

int main(int argc, char **argv)
{
    if (argc < 4) {
        fprintf(stderr, "usage: ztv_gdal_compare ZTV.tif DTM.tif GDAL_1.tif [GDAL_2.tif ...]\n");
        return 2;
    }
    int n_targets = argc - 3;
    if (n_targets > (int)ZTV_MAX_DEVELOPMENTS) {
        fprintf(stderr, "ztv_gdal_compare: at most %u targets (band 4's bits)\n", ZTV_MAX_DEVELOPMENTS);
        return 2;
    }
    GDALAllRegister();
    raster zr, dr;
    float *cls = read_band(TOOL, argv[1], 3, &zr), *count = read_band(TOOL, argv[1], 1, &zr);
    float *seen = read_band(TOOL, argv[1], 4, &zr), *dtm = read_band(TOOL, argv[2], 1, &dr);
    if (!cls || !count || !seen || !dtm) return 2;
    int ok = lined_up(&zr, &dr);
    const int nx = zr.nx, ny = zr.ny;
    const size_t n = (size_t)nx * ny;

    size_t closed = 0, miscounted = 0;
    for (size_t k = 0; k < n; k++) {
        closed += cls[k] != (float)ZTV_OPEN;
        uint32_t bits = (uint32_t)seen[k], pop = 0;
        for (int t = 0; t < n_targets; t++) pop += bits >> t & 1u;
        miscounted += pop != (uint32_t)count[k] || bits >> n_targets;
    }
    if (closed) printf("FAIL: %zu of %zu cells are not viewpoints on bare earth\n", closed, n), ok = 0;
    if (miscounted) printf("FAIL: on %zu cells band 1 does not count band 4's targets\n", miscounted), ok = 0;

    tally all = {0};
    for (int t = 0; t < n_targets; t++) {
        raster gr;
        float *g = read_band(TOOL, argv[3 + t], 1, &gr);
        if (!g) return 2;
        if (gr.nx != nx || gr.ny != ny || gr.gt[0] != dr.gt[0] || gr.gt[3] != dr.gt[3]) {
            printf("FAIL: %s is not on the DTM's pixels\n", argv[3 + t]);
            free(g);
            ok = 0;
            continue;
        }
        tally tt = {0};
        for (int j = 0; j < ny; j++)
            for (int i = 0; i < nx; i++) {
                size_t k = (size_t)j * nx + i;
                int s = (uint32_t)seen[k] >> t & 1u, v = g[k] > 0;
                tt.pairs++, tt.sylva_visible += s, tt.gdal_visible += v;
                if (s == v) continue;
                tt.differ++, tt.only_sylva += s, tt.only_gdal += v;
                tt.edge1 += near_edge(g, seen, t, nx, ny, i, j, 1);
                tt.edge2 += near_edge(g, seen, t, nx, ny, i, j, EDGE_CELLS);
                tt.gdal_edge2 += near_edge(g, NULL, t, nx, ny, i, j, EDGE_CELLS);
            }
        char name[32];
        snprintf(name, sizeof name, "target %d", t + 1);
        print_tally(name, &tt);
        all.pairs += tt.pairs, all.differ += tt.differ, all.only_sylva += tt.only_sylva;
        all.only_gdal += tt.only_gdal, all.edge1 += tt.edge1, all.edge2 += tt.edge2, all.gdal_edge2 += tt.gdal_edge2;
        all.sylva_visible += tt.sylva_visible, all.gdal_visible += tt.gdal_visible;
        free(g);
    }
    print_tally("all", &all);
    double agree = all.pairs ? (double)(all.pairs - all.differ) / all.pairs : 0.0;
    double edge = all.differ ? (double)all.edge2 / all.differ : 1.0;
    if (agree < AGREEMENT_MIN)
        printf("FAIL: sylva and gdal_viewshed agree on %.3f %% of the cells, below %.0f %%\n", 100 * agree,
               100 * AGREEMENT_MIN), ok = 0;
    if (edge < EDGE_SHARE_MIN)
        printf("FAIL: %.1f %% of the differing cells lie within %d cells of a visibility edge, below %.0f %%\n",
               100 * edge, EDGE_CELLS, 100 * EDGE_SHARE_MIN), ok = 0;
    printf("sylva visible cells: %ld\ngdal visible cells: %ld\n", all.sylva_visible, all.gdal_visible);
    free(cls), free(count), free(seen), free(dtm);
    return ok ? 0 : 1;
}
