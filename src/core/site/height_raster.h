/* height_raster.h — a raster of heights (a canopy height model, a surface model, a terrain model)
 * read at the nodes of the site's grid: each node's map coordinates carried into the raster's
 * CRS (through GDAL and PROJ, offline, axes in easting-first order), and the value of the cell
 * the point falls in — the nearest cell, never an interpolated value, so that a treetop keeps its
 * measured height — read from the window of cells under the site a strip of rows at a time, so
 * that a fine model under a large site is never held whole. Files are opened offline
 * (site/gdal_offline.h); the memory a read plans for is checked against the budget
 * (util/memory_budget.h) before it is allocated.
 *
 * Ownership: the caller owns the array the heights are read into. */
#ifndef SYLVA_HEIGHT_RASTER_H
#define SYLVA_HEIGHT_RASTER_H

#include <stdint.h>

#include "site/landcover_source.h" /* landcover_grid: the site grid a map is read onto */
#include "util/err.h"

/* Bytes per node a read plans for besides the caller's array: the node's coordinates and cell. */
#define HEIGHT_RASTER_NODE_BYTES (2 * sizeof(double) + sizeof(int))

/* 0 when path is a raster GDAL reads, with a band, a geotransform and a CRS; otherwise -1 with
 * err set to what it lacks ("it names no CRS ..."; no place, no file name). */
int height_raster_check(const char *path, err_buf *err);

/* Band 1 of path at each node of g into h (g->nx * g->ny floats, row j = 0 south): the cell's
 * value, or NAN where the node falls off the raster, on its no-data value or on a value that is
 * not finite. *covered: the nodes that fall on the raster (no-data cells included). Returns 0, or
 * -1 with err set (no place, no file name): a file GDAL cannot read, no conversion from the site's
 * CRS, out of memory, over the budget. */
int height_raster_read(const char *path, const landcover_grid *g, float *h, uint64_t *covered, err_buf *err);

#endif
