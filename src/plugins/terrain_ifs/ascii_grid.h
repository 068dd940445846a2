/* ascii_grid.h — a cheap completeness check of an ESRI ASCII grid before GDAL reads it.
 *
 * GDAL's AAIGrid reader takes a word where a number belongs as 0 and a short last row as
 * complete, and works for minutes on a grid cut off early when rows are asked for out of order.
 * One pass over the text finds all three: the header's ncols and nrows (and a positive cell
 * size), then exactly ncols x nrows values, each a finite number or the header's NODATA_value
 * (which may be nan). Messages say where the grid goes wrong (path:line:column for a bad cell
 * size or a value that is not finite), never what the file holds there. */
#ifndef TERRAIN_IFS_ASCII_GRID_H
#define TERRAIN_IFS_ASCII_GRID_H

#include "plugin_err.h"

/* SYLVA_OK when path is not an ESRI ASCII grid (its first word is not "ncols") or is a complete
 * one; SYLVA_ERR_IO with a sentence naming `what` and path otherwise. */
int ifs_ascii_grid_check(const char *path, const char *what, plugin_err *err);

#endif
