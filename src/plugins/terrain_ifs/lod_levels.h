/* lod_levels.h — levels of detail of the refined terrain around the camera: which windows of
 * the DTM's cells are refined at which resolution, and the pinning of each level's rim onto the
 * coarser level around it so that the levels meet without cracks (docs/models/terrain_ifs.md,
 * "Levels of detail").
 *
 * The DTM's own nodes cover the whole footprint (refine 1). Around the camera's position, rings
 * of halving resolution: the finest level, at the scene's refine R, is a square window of
 * half-width `radius` (in DTM cells) around the eye; the next coarser one, at R / 2, has twice
 * the half-width; and so on while the refine stays a whole number above 1 (R = 6: 6, 3). Each
 * window is aligned to DTM cells and clipped to the footprint; a level whose window would hold
 * no cell is left out with every finer one. Nothing is allocated. */
#ifndef TERRAIN_IFS_LOD_LEVELS_H
#define TERRAIN_IFS_LOD_LEVELS_H

#include <stdint.h>

#define IFS_LOD_MAX_LEVELS 12u

typedef struct ifs_lod_window {
    uint32_t i0, j0;          /* south-west DTM node */
    uint32_t cells_x, cells_y;/* DTM cells */
    uint32_t refine;          /* nodes per DTM cell along each axis */
} ifs_lod_window;

/* The windows, coarse to fine, into w (IFS_LOD_MAX_LEVELS); returns their number. ncx, ncy: the
 * DTM's cells; (ex, ey): the eye in DTM cell units from node (0, 0) (any finite numbers; an eye
 * off the footprint refines the part nearest to it); radius: half-width of the finest window
 * in DTM cells, > 0. Each window lies strictly inside the one before it, except on the
 * footprint's edge. */
uint32_t ifs_lod_windows(uint32_t ncx, uint32_t ncy, uint32_t refine, double ex, double ey,
                         double radius, ifs_lod_window *w);

/* Sets the nodes on the rim of level `fine` (its window's four sides) onto the surface of the
 * coarser level `coarse` around it: linear along the side between the coarser level's nodes.
 * A side on the footprint's edge is set too, so the footprint's edge is the same line at every
 * level and the apron beyond it (geometry/terrain_apron.h) meets it there. z_fine, z_coarse:
 * their heights, row-major, row 0 south. */
void ifs_lod_pin_rim(const ifs_lod_window *coarse, const float *z_coarse, const ifs_lod_window *fine,
                     float *z_fine);

#endif
