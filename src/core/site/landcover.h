/* landcover.h — a land-cover map read onto a site: a classified raster (through GDAL, in any CRS,
 * with square or oblong cells) or polygons (through OGR, classed by one attribute), sampled once
 * at every node of the ground as surveyed and turned into the scene's land_cover
 * (scene/land_cover.h) through a legend (site/landcover_legend.h) and the classes the scene
 * names.
 *
 * Classes are never interpolated: a node takes the class of the raster cell it falls in, or of
 * the polygon that holds it. A node off the map, or on a no-data cell, has no class; such nodes
 * are counted and reported. Files are opened offline (site/gdal_offline.h), and the memory a read
 * plans for is checked against the budget (util/memory_budget.h) before it is allocated.
 *
 * Ownership: landcover_read returns a land_cover the caller frees with land_cover_free. */
#ifndef SYLVA_LANDCOVER_H
#define SYLVA_LANDCOVER_H

#include <stdint.h>
#include <stdio.h>

#include "scene/land_cover.h"
#include "site/landcover_source.h"
#include "util/err.h"

/* Opens the map as the scene file is read and checks what can be checked without the site's
 * grid: a raster GDAL reads, georeferenced, with a CRS; a vector file with the layer and the
 * class field. Returns 0, or -1 with err set (no place) and *fault naming the key at fault. */
int landcover_check(const landcover_source *src, landcover_fault *fault, err_buf *err);

/* Reads the map onto the grid. warnings: where the codes the legend lacks are reported, summary:
 * where the one line on the map, its legend and the kinds' shares goes (either NULL: none).
 * Returns the land cover, or NULL with err set (no place): a map that covers none of the grid, a
 * file GDAL cannot read, out of memory, over the budget. */
land_cover *landcover_read(const landcover_source *src, const landcover_grid *grid, FILE *warnings,
                          FILE *summary, err_buf *err);

#endif
