/* lod_levels.c — level-of-detail windows and rim pinning (see lod_levels.h). */
#include "lod_levels.h"

#include <math.h>
#include <stddef.h>

/* [lo, hi) of cells of a window of half-width h around e on an axis of n cells. */
static void axis_window(double e, double h, uint32_t n, uint32_t *lo, uint32_t *hi)
{
    double a = floor(e - h), b = ceil(e + h);
    if (a < 0) a = 0;
    if (b > n) b = n;
    if (a > n) a = n;
    if (b < 0) b = 0;
    *lo = (uint32_t)a, *hi = (uint32_t)(b > a ? b : a);
}

uint32_t ifs_lod_windows(uint32_t ncx, uint32_t ncy, uint32_t refine, double ex, double ey,
                         double radius, ifs_lod_window *w)
{
    uint32_t refines[IFS_LOD_MAX_LEVELS], n = 0;
    for (uint32_t r = refine; r > 1 && n < IFS_LOD_MAX_LEVELS; r = r % 2 ? 1 : r / 2) refines[n++] = r;
    if (!isfinite(ex) || !isfinite(ey)) ex = 0.5 * ncx, ey = 0.5 * ncy;
    /* the eye clamped onto the footprint: the nearest part of it is refined */
    ex = ex < 0 ? 0 : ex > ncx ? ncx : ex;
    ey = ey < 0 ? 0 : ey > ncy ? ncy : ey;
    uint32_t levels = 0;
    for (uint32_t k = n; k-- > 0;) { /* coarse (the last refine) to fine */
        double h = radius * (double)(1u << k);
        uint32_t i0, i1, j0, j1;
        axis_window(ex, h, ncx, &i0, &i1);
        axis_window(ey, h, ncy, &j0, &j1);
        if (levels) { /* strictly inside the coarser window, except on the footprint's edge */
            const ifs_lod_window *c = &w[levels - 1];
            if (i0 <= c->i0 && i0 > 0) i0 = c->i0 + 1;
            if (j0 <= c->j0 && j0 > 0) j0 = c->j0 + 1;
            if (i1 >= c->i0 + c->cells_x && i1 < ncx) i1 = c->i0 + c->cells_x - 1;
            if (j1 >= c->j0 + c->cells_y && j1 < ncy) j1 = c->j0 + c->cells_y - 1;
        }
        if (i1 <= i0 || j1 <= j0) break;
        w[levels++] = (ifs_lod_window){i0, j0, i1 - i0, j1 - j0, refines[k]};
    }
    return levels;
}

/* The coarser level's height at fine-level node (fi, fj) on a side: linear between the coarser
 * nodes along the side (along x when along_x, else along y). */
static float coarse_on_side(const ifs_lod_window *c, const float *zc, const ifs_lod_window *f,
                            uint32_t fi, uint32_t fj, int along_x)
{
    uint32_t m = f->refine / c->refine, cnx = c->cells_x * c->refine + 1;
    /* the node in the coarser level's index units, times m */
    uint64_t gi = (uint64_t)(f->i0 - c->i0) * f->refine + fi, gj = (uint64_t)(f->j0 - c->j0) * f->refine + fj;
    uint64_t ci = gi / m, cj = gj / m, ri = gi % m, rj = gj % m;
    const float *row = zc + cj * cnx;
    if (along_x) {
        if (!ri) return row[ci];
        return row[ci] + (float)ri / (float)m * (row[ci + 1] - row[ci]);
    }
    if (!rj) return row[ci];
    return row[ci] + (float)rj / (float)m * (row[ci + cnx] - row[ci]);
}

void ifs_lod_pin_rim(const ifs_lod_window *coarse, const float *z_coarse, const ifs_lod_window *fine,
                     float *z_fine)
{
    uint32_t nx = fine->cells_x * fine->refine + 1, ny = fine->cells_y * fine->refine + 1;
    for (uint32_t i = 0; i < nx; i++) {
        z_fine[i] = coarse_on_side(coarse, z_coarse, fine, i, 0, 1);
        z_fine[(size_t)(ny - 1) * nx + i] = coarse_on_side(coarse, z_coarse, fine, i, ny - 1, 1);
    }
    for (uint32_t j = 0; j < ny; j++) {
        z_fine[(size_t)j * nx] = coarse_on_side(coarse, z_coarse, fine, 0, j, 0);
        z_fine[(size_t)j * nx + nx - 1] = coarse_on_side(coarse, z_coarse, fine, nx - 1, j, 0);
    }
}
