/* canopy.h — the canopy of a site as the scene holds it: the height of the vegetation's top
 * above the ground at each node of the ground as surveyed (scene.surveyed), from a canopy height
 * model or a surface model less the terrain model (site/canopy_read.h). Read by the visibility
 * map's canopy screening (ztv/ztv_canopy.h) and by the scene build, which scales the plants to
 * it (scene_build/scene_canopy.h).
 *
 * Ownership: a canopy owns its height array and its source string; canopy_free releases them. */
#ifndef SYLVA_CANOPY_H
#define SYLVA_CANOPY_H

#include <stdint.h>

typedef struct canopy {
    uint32_t nx, ny;         /* the grid of scene.surveyed: node (i, j) at (x0 + i dx, y0 + j dy) */
    double x0, y0, dx, dy;
    float *height;           /* nx * ny, row j = 0 south: metres above the ground, >= 0, or NAN
                                where the model has no data (off it, or on a no-data cell); owned */
    uint64_t no_data;        /* nodes whose height is NAN */
    char *source;            /* the model's file name(s), for messages; owned */
} canopy;

void canopy_free(canopy *c); /* accepts NULL */

/* The height at the node nearest (x, y) (local metres): metres above the ground, or NAN where the
 * model has no data or (x, y) lies off the grid by more than half a spacing. */
double canopy_height_at(const canopy *c, double x, double y);

/* The height of node k, no data taken as no canopy (0). */
static inline float canopy_height_or_open(const canopy *c, uint64_t k)
{
    float h = c->height[k];
    return h == h ? h : 0.0f;
}

#endif
