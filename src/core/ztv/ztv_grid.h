/* ztv_grid.h — the cells of a visibility map: by default one per node of the DTM as surveyed
 * (scene.surveyed), whichever ground the map traces, or cells of a given size on the same lattice
 * origin; cut to the square around the targets that the radius reaches, and to the terrain. */
#ifndef SYLVA_ZTV_GRID_H
#define SYLVA_ZTV_GRID_H

#include "scene/scene.h"
#include "util/err.h"
#include "ztv/ztv_raster.h"
#include "ztv/ztv_targets.h"

#define ZTV_MAX_CELLS_SIDE 1000000u /* cells along either side of a map */
#define ZTV_MAX_SIGHTLINES 1e13    /* cells x targets: about a month of tracing on two cores */

/* The grid for cell size `cell` (0: the surveyed DTM's node spacing) and `radius` (INFINITY: the
 * whole terrain) into *g. Returns 0, or -1 with err set (no terrain, the targets' reach misses
 * it, a grid beyond ZTV_MAX_CELLS_SIDE, or more than ZTV_MAX_SIGHTLINES cells x targets). */
int ztv_grid_make(const scene *s, const ztv_targets *t, double cell, double radius, ztv_grid *g, err_buf *err);

/* Local centre of cell (i, j). */
static inline void ztv_cell_centre(const ztv_grid *g, uint32_t i, uint32_t j, double *x, double *y)
{
    *x = g->x0 + i * g->cell;
    *y = g->y0 - j * g->cell;
}

#endif
