/* raster_nodes.h — band 1 of a georeferenced raster read at the site grid's nodes, the one way
 * sylva samples a raster map onto its ground (land-cover classes, canopy and surface heights):
 * each node's map coordinates carried into the raster's CRS (GIS axis order), and the value of
 * the cell the point falls in — the nearest cell, never an interpolated value, so that a class
 * stays a class and a treetop keeps its measured height — read from the window of cells under
 * the site a strip of rows at a time, so that a fine map under a large site is never held
 * whole. The strip's memory is checked against the budget (util/memory_budget.h) before it is
 * allocated. */
#ifndef SYLVA_RASTER_NODES_H
#define SYLVA_RASTER_NODES_H

#include <stddef.h>
#include <stdint.h>

#include <gdal.h>
#include <ogr_srs_api.h>

#include "site/landcover_source.h" /* landcover_grid: the site grid a map is read onto */
#include "util/err.h"

/* Called for each node k whose point falls on the raster with its cell's value; no_data is 1
 * when the value is the band's no-data value or not a finite number. */
typedef void (*raster_node_fn)(void *ctx, size_t k, double value, int no_data);

/* The raster's spatial reference in GIS axis order (a clone the caller releases with
 * OSRRelease), or NULL when it names none. */
OGRSpatialReferenceH raster_nodes_srs(GDALDatasetH ds);

/* Reads band 1 of ds at every node of g (node k = j * g->nx + i, row j = 0 south), calling
 * visit for the nodes on the raster; *covered counts them. `what` names the cells in messages
 * ("the land-cover map's cells"). Returns 0, or -1 with err set (no place, no file name): no
 * georeferencing or CRS, no conversion from the site's CRS, a read GDAL refuses, out of memory,
 * over the budget. */
int raster_nodes_read(GDALDatasetH ds, const landcover_grid *g, const char *what, raster_node_fn visit, void *ctx,
                      uint64_t *covered, err_buf *err);

#endif
