/* ztv_grid.c — the map's cells over the terrain and the radius, and the limits on its work. */
#include "ztv/ztv_grid.h"

#include <math.h>
#include <stdio.h>

static const char *const edge_names[ZTV_EDGES] = {"west", "east", "south", "north"};

/* The cell size, rounded up to 3 significant digits, at which a count that falls as
 * 1 / cell^power comes down from `count` at `cell` to `limit`. */
static double cell_to_fit(double cell, double count, double limit, double power)
{
    double c = cell * pow(count / limit, 1.0 / power);
    double unit = pow(10, floor(log10(c)) - 2);
    return ceil(c / unit * (1 - 1e-12)) * unit;
}

/* The lattice columns (or rows) whose centres lie in [a, b], counted from `from` at steps of
 * cell (a small tolerance keeps the terrain's own edge nodes): first and last into *k0, *k1. */
static void lattice_span(double from, double a, double b, double cell, double *k0, double *k1)
{
    double eps = 1e-9 * cell;
    *k0 = ceil((a - from) / cell - eps), *k1 = floor((b - from) / cell + eps);
}

int ztv_grid_make(const scene *s, const ztv_targets *t, double cell, double radius, ztv_grid *g, err_buf *err)
{
    const sylva_heightfield *h = s->terrain;
    if (!h) return err_set(err, "the scene has no terrain to map; add a 'terrain:' section");
    if (cell <= 0) cell = fmax(s->surveyed->dx, s->surveyed->dy); /* the DTM's cells, whichever ground */
    /* the terrain's extent, and the lattice: cell centres at x0 + i cell, y = north - j cell */
    double west = h->x0, east = h->x0 + (h->nx - 1) * h->dx;
    double south = h->y0, north = h->y0 + (h->ny - 1) * h->dy;
    double lo[2] = {west, south}, hi[2] = {east, north}; /* the map */
    double past[ZTV_EDGES] = {0};
    if (isfinite(radius)) {
        double tlo[2] = {INFINITY, INFINITY}, thi[2] = {-INFINITY, -INFINITY};
        for (uint32_t k = 0; k < t->n; k++)
            for (int a = 0; a < 2; a++) tlo[a] = fmin(tlo[a], t->p[k][a]), thi[a] = fmax(thi[a], t->p[k][a]);
        for (int a = 0; a < 2; a++) lo[a] = tlo[a] - radius, hi[a] = thi[a] + radius;
        if (fmax(lo[0], west) > fmin(hi[0], east) || fmax(lo[1], south) > fmin(hi[1], north))
            return err_set(err, "no terrain lies within the radius of %g m of the targets", radius);
        past[ZTV_WEST] = fmax(0, west - lo[0]), past[ZTV_EAST] = fmax(0, hi[0] - east);
        past[ZTV_SOUTH] = fmax(0, south - lo[1]), past[ZTV_NORTH] = fmax(0, hi[1] - north);
    }
    double i0, i1, j0, j1; /* the map's first and last columns and rows */
    lattice_span(west, lo[0], hi[0], cell, &i0, &i1);
    lattice_span(-north, -hi[1], -lo[1], cell, &j0, &j1);
    if (i1 < i0 || j1 < j0) return err_set(err, "the map has no cell: the cell of %g m is larger than the area", cell);
    double nx = i1 - i0 + 1, ny = j1 - j0 + 1, longest = fmax(nx, ny);
    if (longest > ZTV_MAX_CELLS_SIDE)
        return err_fail(err, ERR_LIMIT,
                        "the map would be %.0f x %.0f cells of %g m; at most %u a side: a cell of at least %g m "
                        "(--cell or ztv: cell) or a smaller radius",
                        nx, ny, cell, ZTV_MAX_CELLS_SIDE, cell_to_fit(cell, longest, ZTV_MAX_CELLS_SIDE, 1));
    if (nx * ny > ZTV_MAX_CELLS)
        return err_fail(err, ERR_LIMIT,
                        "the map would be %.0f x %.0f cells of %g m, %.3g cells, more than the %.0e a map may "
                        "hold: a cell of at least %g m (--cell or ztv: cell) or a smaller radius",
                        nx, ny, cell, nx * ny, ZTV_MAX_CELLS, cell_to_fit(cell, nx * ny, ZTV_MAX_CELLS, 2));
    /* the cells traced: those on the terrain */
    double ti0, ti1, tj0, tj1;
    lattice_span(west, fmax(lo[0], west), fmin(hi[0], east), cell, &ti0, &ti1);
    lattice_span(-north, -fmin(hi[1], north), -fmax(lo[1], south), cell, &tj0, &tj1);
    double traced = fmax(0, ti1 - ti0 + 1) * fmax(0, tj1 - tj0 + 1), work = traced * t->n;
    if (work > ZTV_MAX_SIGHTLINES)
        return err_fail(err, ERR_LIMIT,
                        "%.0f cells of %g m on the terrain and %u targets are %.3g sightlines, more than the %.0e a "
                        "map may trace: a cell of at least %g m (--cell or ztv: cell), a smaller radius or at most "
                        "%.0f targets",
                        traced, cell, t->n, work, ZTV_MAX_SIGHTLINES,
                        cell_to_fit(cell, work, ZTV_MAX_SIGHTLINES, 2), floor(ZTV_MAX_SIGHTLINES / traced));
    *g = (ztv_grid){.nx = (uint32_t)nx, .ny = (uint32_t)ny, .x0 = west + i0 * cell, .y0 = north - j0 * cell,
                    .cell = cell};
    for (int e = 0; e < ZTV_EDGES; e++) g->past_edge[e] = past[e];
    return 0;
}

int ztv_grid_past_edge_text(const ztv_grid *g, double radius, char *buf, size_t size)
{
    size_t used = 0;
    int n = 0;
    buf[0] = '\0';
    for (int e = 0; e < ZTV_EDGES; e++) {
        if (!(g->past_edge[e] > 0)) continue;
        int w = n ? snprintf(buf + used, size - used, " and %.12g m past its %s edge", g->past_edge[e], edge_names[e])
                  : snprintf(buf + used, size - used, "the radius of %.12g m reaches %.1f m past the terrain's %s edge",
                             radius, g->past_edge[e], edge_names[e]);
        if (w < 0 || (size_t)w >= size - used) break;
        used += (size_t)w, n++;
    }
    return n ? 0 : -1;
}
