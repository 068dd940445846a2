/* dtm.h — the digital terrain model the IFS interpolates: a regular grid of surveyed heights
 * z(x_n, y_m) in metres (MODELS.md §1, "Input"), whatever it came from (a GDAL raster, the
 * scene's inline grid or the seeded generator), and the filling of its nodata nodes.
 *
 * Ownership: an ifs_dtm owns its height array; ifs_dtm_free releases both and accepts NULL.
 */
#ifndef TERRAIN_IFS_DTM_H
#define TERRAIN_IFS_DTM_H

#include <stdint.h>

#include "plugin_err.h"

/* Size limits of a DTM after cropping and resampling. Each axis needs two cells at least: with
 * one cell the map L_n (8) is the identity and the IFS does not contract along that axis. The
 * node count has no fixed limit: the plugin weighs the whole work against the host's memory
 * budget before reading (IFS_DTM_BYTES_PER_NODE here, docs/models/terrain_ifs.md). */
#define IFS_DTM_MIN_SIDE 3u
#define IFS_DTM_MAX_SIDE 65536u
#define IFS_DTM_BYTES_PER_NODE 8u /* one double height; the maps are not stored (ifs_maps.h) */

typedef struct ifs_dtm {
    uint32_t nx, ny; /* nodes along x (west to east) and y (south to north) */
    double dx, dy;   /* node spacing along x and y, metres, > 0 */
    double *z;       /* nx * ny heights in metres, row-major, row 0 the southern edge; NaN marks
                        nodata until ifs_dtm_fill_nodata; owned */
} ifs_dtm;

/* A new DTM with zeroed heights. Fails (status and sentence) when a side is outside
 * [IFS_DTM_MIN_SIDE, IFS_DTM_MAX_SIDE], a spacing is not a positive finite number, or memory
 * runs out. */
int ifs_dtm_new(uint32_t nx, uint32_t ny, double dx, double dy, ifs_dtm **out, plugin_err *err);
void ifs_dtm_free(ifs_dtm *d);

/* The size rule of ifs_dtm_new alone, so callers can refuse a grid before reading it. */
int ifs_dtm_check_size(uint32_t nx, uint32_t ny, plugin_err *err);

/* A DTM from rows of heights, row 0 the southern edge (the scene file's grid order). */
int ifs_dtm_from_rows(const double *rows, uint32_t cols, uint32_t nrows, double dx, double dy,
                      ifs_dtm **out, plugin_err *err);

/* Lowest and highest finite height (0 and 0 when there is none). */
void ifs_dtm_range(const ifs_dtm *d, double *zmin, double *zmax);

/* Fills every NaN node from its neighbours, ring by ring from the edge of each hole inwards:
 * a node takes the weighted mean of the 8 neighbours already known before its ring (weight 1
 * for the four side neighbours, 1/sqrt(2) for the diagonals). *filled receives the number of
 * nodes filled. Fails when every node is nodata. Deterministic; O(nodes). */
int ifs_dtm_fill_nodata(ifs_dtm *d, uint64_t *filled, plugin_err *err);

#endif
