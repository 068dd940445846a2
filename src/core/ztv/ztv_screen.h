/* ztv_screen.h — what a screening sightline is traced against once bare earth has left the pair
 * clear (a pair bare earth hides is hidden screened too, so only those are asked): the accel's
 * plants and objects whose ray mask the screened mode names. They are traced without the ground:
 * either in an Embree scene of their own, or in the top scene with a mask that leaves the ground
 * out. The top scene's BVH holds the terrain's grid among the plants, so a sightline running a
 * couple of metres over the ground walks the terrain's nodes all the way; a scene of their own
 * spares that walk but costs a BVH over every instance the accel holds, so it is built when the map
 * traces at least ZTV_SCREEN_PAIRS_PER_PLANT pairs per instance held (measured: its build costs
 * about as much as the walks it spares over 4 to 5 sightlines an instance, and about half the pairs
 * clear bare earth). Either way a sightline clear of the ground and of these is clear of the top
 * scene with the screened mode's mask: the same geometries (their filters, transforms and ids).
 *
 * Ownership: ztv_screen_open may make an Embree scene on the accel's device (which must outlive
 * it); ztv_screen_close releases it.
 */
#ifndef SYLVA_ZTV_SCREEN_H
#define SYLVA_ZTV_SCREEN_H

#include <embree3/rtcore.h>
#include <stdint.h>

#include "render/accel.h"
#include "util/err.h"

#define ZTV_SCREEN_PAIRS_PER_PLANT 8

typedef struct ztv_screen {
    RTCScene scene; /* to trace: own, or the accel's top scene */
    unsigned mask;  /* the ray mask to trace with */
    RTCScene own;   /* the plants' and objects' own scene, or NULL; owned */
} ztv_screen;

/* The screening geometry of a (plant instances and objects whose mask meets mask; the ground
 * aside) for a map of `pairs` observer-target pairs. Returns 0, or -1 with err set on an Embree
 * error. */
int ztv_screen_open(ztv_screen *s, const accel *a, unsigned mask, uint64_t pairs, err_buf *err);
void ztv_screen_close(ztv_screen *s); /* accepts a zeroed one */

#endif
