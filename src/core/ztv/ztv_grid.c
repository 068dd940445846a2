/* ztv_grid.c — the map's cells over the terrain. */
#include "ztv/ztv_grid.h"

#include <math.h>

int ztv_grid_make(const scene *s, const ztv_targets *t, double cell, double radius, ztv_grid *g, err_buf *err)
{
    const sylva_heightfield *h = s->terrain;
    if (!h) return err_set(err, "the scene has no terrain to map; add a 'terrain:' section");
    if (cell <= 0) cell = fmax(s->surveyed->dx, s->surveyed->dy); /* the DTM's cells, whichever ground */
    /* the terrain's extent, and the lattice: cell centres at x0 + i cell, y = north - j cell */
    double west = h->x0, east = h->x0 + (h->nx - 1) * h->dx;
    double south = h->y0, north = h->y0 + (h->ny - 1) * h->dy;
    double lo[2] = {west, south}, hi[2] = {east, north};
    if (isfinite(radius)) {
        double tlo[2] = {INFINITY, INFINITY}, thi[2] = {-INFINITY, -INFINITY};
        for (uint32_t k = 0; k < t->n; k++)
            for (int a = 0; a < 2; a++) tlo[a] = fmin(tlo[a], t->p[k][a]), thi[a] = fmax(thi[a], t->p[k][a]);
        for (int a = 0; a < 2; a++) lo[a] = fmax(lo[a], tlo[a] - radius), hi[a] = fmin(hi[a], thi[a] + radius);
        if (lo[0] > hi[0] || lo[1] > hi[1])
            return err_set(err, "no terrain lies within the radius of %g m of the targets", radius);
    }
    /* the first and last lattice columns and rows inside [lo, hi] (a small tolerance keeps the
     * terrain's own edge nodes) */
    double eps = 1e-9 * cell;
    double i0 = ceil((lo[0] - west) / cell - eps), i1 = floor((hi[0] - west) / cell + eps);
    double j0 = ceil((north - hi[1]) / cell - eps), j1 = floor((north - lo[1]) / cell + eps);
    if (i1 < i0 || j1 < j0) return err_set(err, "the map has no cell: the cell of %g m is larger than the area", cell);
    if (i1 - i0 + 1 > ZTV_MAX_CELLS_SIDE || j1 - j0 + 1 > ZTV_MAX_CELLS_SIDE)
        return err_set(err, "the map would be %.0f x %.0f cells; at most %u a side (a larger cell or a radius)",
                       i1 - i0 + 1, j1 - j0 + 1, ZTV_MAX_CELLS_SIDE);
    double work = (i1 - i0 + 1) * (j1 - j0 + 1) * (double)t->n;
    if (work > ZTV_MAX_SIGHTLINES)
        return err_fail(err, ERR_LIMIT,
                        "%.0f x %.0f cells and %u targets are %.3g sightlines, more than the %.0e a map may "
                        "trace (a larger cell, a radius or fewer targets)",
                        i1 - i0 + 1, j1 - j0 + 1, t->n, work, ZTV_MAX_SIGHTLINES);
    *g = (ztv_grid){.nx = (uint32_t)(i1 - i0 + 1), .ny = (uint32_t)(j1 - j0 + 1), .x0 = west + i0 * cell,
                    .y0 = north - j0 * cell, .cell = cell};
    return 0;
}
