/* ztv_grid.h — the cells of a visibility map: by default one per node of the DTM as surveyed
 * (scene.surveyed), whichever ground the map traces, or cells of a given size on the same lattice
 * origin; the whole terrain, or the square around the targets that the radius reaches (past the
 * terrain's edge too: those cells are mapped as having no terrain, and how far the radius runs
 * past each edge is kept). Work beyond what a map may hold or trace is refused here, before
 * anything is allocated or traced. */
#ifndef SYLVA_ZTV_GRID_H
#define SYLVA_ZTV_GRID_H

#include <stddef.h>

#include "scene/scene.h"
#include "util/err.h"
#include "ztv/ztv_raster.h"
#include "ztv/ztv_targets.h"

#define ZTV_MAX_CELLS_SIDE 1000000u /* cells along either side of a map */
#define ZTV_MAX_CELLS 1e9           /* cells of a map: its GeoTIFFs hold 16 bytes a cell per mode, and
                                     * each cell on the terrain costs a ground height and a sightline
                                     * at least (about 15 minutes on two cores) */
#define ZTV_MAX_SIGHTLINES 1e12     /* cells on the terrain x targets: about two days of tracing on
                                     * two cores at the 6e6 sightlines a second of a wind farm */

/* The grid for cell size `cell` (0: the surveyed DTM's node spacing) and `radius` (INFINITY: the
 * whole terrain) into *g. Returns 0, or -1 with err set (no terrain, the targets' reach misses
 * it, a grid beyond ZTV_MAX_CELLS_SIDE a side or ZTV_MAX_CELLS in all, or more than
 * ZTV_MAX_SIGHTLINES cells on the terrain x targets: the message gives the cell size that would
 * fit). */
int ztv_grid_make(const scene *s, const ztv_targets *t, double cell, double radius, ztv_grid *g, err_buf *err);

/* "the radius of R m reaches 12.5 m past the terrain's west edge and 3 m past its north edge"
 * into buf (size bytes) when the radius runs past the terrain; returns 0 then, -1 (buf
 * empty) when it stays within. */
int ztv_grid_past_edge_text(const ztv_grid *g, double radius, char *buf, size_t size);

/* Local centre of cell (i, j). */
static inline void ztv_cell_centre(const ztv_grid *g, uint32_t i, uint32_t j, double *x, double *y)
{
    *x = g->x0 + i * g->cell;
    *y = g->y0 - j * g->cell;
}

#endif
