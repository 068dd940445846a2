/* canopy_read.h — a site's canopy heights read onto its grid (scene/canopy.h): from a canopy
 * height model (CHM: the vegetation's top above the ground, as LiDAR or photogrammetry surveys
 * deliver it), or from a surface model (DSM: the top of everything, in elevations) less the
 * terrain model under it (DTM), each sampled at every node of the ground as surveyed by
 * site/height_raster.h (any CRS, the nearest cell).
 *
 * A node off the model or on a no-data cell has no height (NAN, counted and reported). Heights
 * below the ground (noise in a CHM, a DSM below its DTM) are taken as no canopy, and those more
 * than CANOPY_BELOW_GROUND_WARN below it are counted in a warning. A model whose heights average
 * above CANOPY_MEAN_MAX holds elevations, not heights, and is refused.
 *
 * Ownership: canopy_read returns a canopy the caller frees with canopy_free. */
#ifndef SYLVA_CANOPY_READ_H
#define SYLVA_CANOPY_READ_H

#include <stdio.h>

#include "scene/canopy.h"
#include "site/landcover_source.h" /* landcover_grid: the site grid */
#include "util/err.h"

#define CANOPY_BELOW_GROUND_WARN 0.5 /* metres below the ground that a height is counted in a warning */
#define CANOPY_MEAN_MAX 100.0        /* metres: a mean height above it is a model of elevations */
#define CANOPY_TALL 2.0              /* metres: the summary gives the share of the nodes above it */

/* Where the heights come from: chm alone, or dsm and dtm (the paths resolved). */
typedef struct canopy_source {
    const char *chm;
    const char *dsm, *dtm;
} canopy_source;

/* Which file a fault lies in, so that the caller can place the message at its key. */
typedef enum canopy_fault { CANOPY_FAULT_CHM = 0, CANOPY_FAULT_DSM, CANOPY_FAULT_DTM } canopy_fault;

/* Opens each file as the scene file is read and checks what can be checked without the site's
 * grid: a raster GDAL reads, georeferenced, with a CRS. Returns 0, or -1 with err set (no place)
 * and *fault naming the file at fault. */
int canopy_check(const canopy_source *src, canopy_fault *fault, err_buf *err);

/* Reads the heights onto grid. warnings: where the heights below the ground are reported;
 * summary: where the one line on the canopy goes (either NULL: none). Returns the canopy, or NULL
 * with err set (no place) and *fault naming the file at fault: a model that covers none of the
 * grid, one of elevations, a file GDAL cannot read, out of memory, over the budget. */
canopy *canopy_read(const canopy_source *src, const landcover_grid *grid, FILE *warnings, FILE *summary,
                    canopy_fault *fault, err_buf *err);

#endif
