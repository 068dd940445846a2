/* ztv_cover.h — which cells' observers stand under a tree crown or inside an object: such a
 * cell is no viewpoint in the modes that hold the plants or the objects (ztv_raster.h).
 *
 * Under a crown: each prototype's footprint is a grid of ZTV_FOOTPRINT x ZTV_FOOTPRINT bins over
 * its horizontal extent, a bin holding the highest point of the triangles whose extent covers
 * it; an observer stands under a plant when the bin under the eye, carried through the
 * plant's transform, holds a point above the eye (a branch, a leaf or the trunk overhead).
 * Inside an object: a ray straight up from the eye crosses the objects' surfaces an odd number
 * of times (inside a closed mesh), or it meets an open one (a roof over the eye); only cells
 * inside an object's bounding box are asked.
 *
 * Ownership: ztv_cover_new allocates the footprints and the plants' index; ztv_cover_free
 * releases them. The scene and the accel are borrowed and must outlive it.
 */
#ifndef SYLVA_ZTV_COVER_H
#define SYLVA_ZTV_COVER_H

#include "render/accel.h"
#include "scene/scene.h"
#include "ztv/ztv_raster.h"

#define ZTV_FOOTPRINT 32u

typedef struct ztv_cover ztv_cover;

/* NULL with err set when out of memory. */
ztv_cover *ztv_cover_new(const scene *s, const accel *a, const ztv_grid *g, err_buf *err);
void ztv_cover_free(ztv_cover *c); /* accepts NULL */

/* For the cells of row j (g->nx of them) whose eye is at eye_z (NAN: no observer), sets
 * under[i] to 1 where a plant stands over the eye (and leaves the others as they are). */
void ztv_cover_crowns(const ztv_cover *c, uint32_t j, const float *eye_z, uint8_t *under);

/* The same for objects: inside[i] = 1 where the eye is inside or under an object. */
void ztv_cover_objects(const ztv_cover *c, uint32_t j, const float *eye_z, uint8_t *inside);

#endif
