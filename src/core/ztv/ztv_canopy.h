/* ztv_canopy.h — the canopy surface a visibility map screens with in its canopy mode: at each node
 * of the ground as surveyed, the ground the map traces there plus the canopy's height above it
 * (scene/canopy.h; no data is no canopy), two triangles per cell split as the terrain is (the
 * diagonal from node (i, j) to (i + 1, j + 1)), as an Embree grid geometry in a scene of its own
 * on the accel's device. In canopy mode a sightline is clear when it clears the ground (the
 * accel's top scene, bare-earth mask) and this surface: the canopy hides what lies behind it as a
 * digital surface model would, while the observers stay at eye height above the bare ground. An
 * observer whose eye is below the surface at the cell's centre stands under the canopy and is no
 * viewpoint (ZTV_UNDER_CROWN).
 *
 * Memory: 16 bytes per node here (its height and its vertex) and Embree's grid BVH (about 20
 * bytes per node at the peak of its build), checked against the budget before anything is built.
 *
 * Ownership: ztv_canopy_new allocates the surface's heights and vertices and the Embree scene;
 * ztv_canopy_free releases them. The scene and the accel are borrowed and must outlive it.
 */
#ifndef SYLVA_ZTV_CANOPY_H
#define SYLVA_ZTV_CANOPY_H

#include <embree3/rtcore.h>

#include "render/accel.h"
#include "scene/scene.h"
#include "util/err.h"
#include "ztv/ztv_raster.h"

typedef struct ztv_canopy ztv_canopy;

/* The surface of s's canopy over s's ground. NULL with err set: no canopy in the scene, a canopy
 * on another grid than the surveyed ground's, out of memory, over the budget, an Embree error. */
ztv_canopy *ztv_canopy_new(const scene *s, const accel *a, err_buf *err);
void ztv_canopy_free(ztv_canopy *c); /* accepts NULL */

/* The Embree scene holding the surface alone (any ray mask meets it). */
RTCScene ztv_canopy_scene(const ztv_canopy *c);

/* For the cells of row j of grid g (g->nx of them) whose eye is at eye_z (NAN: no observer),
 * sets under[i] to 1 where the canopy surface stands above the eye (and leaves the others). */
void ztv_canopy_under(const ztv_canopy *c, const ztv_grid *g, uint32_t j, const float *eye_z, uint8_t *under);

#endif
