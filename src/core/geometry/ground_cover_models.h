/* ground_cover_models.h — the plants of the ground cover as procedural meshes: tufts of grass
 * (thin tapered blades, each a strip of triangles curving away from the vertical) and flowering
 * herbs (a rosette of leaves, a stem and a flower head), in the leaf material (two-sided,
 * diffusely translucent). Each is built once as a prototype of its own species, "ground cover
 * grass" or "ground cover herb", and placed many times (ground_cover_place.h).
 *
 * The shapes come from a stream keyed by the scene seed and the variant, so a scene builds the
 * same models every time. Nothing is kept besides what is added to the scene. */
#ifndef SYLVA_GROUND_COVER_MODELS_H
#define SYLVA_GROUND_COVER_MODELS_H

#include <stdint.h>

#include "scene/scene.h"

#define GROUND_COVER_GRASS_VARIANTS 3 /* a short and a tall green tuft, one with dry blades */
#define GROUND_COVER_HERB_VARIANTS 2  /* a white-flowered and a yellow-flowered forb */
#define GROUND_COVER_BLADE_LENGTH 0.3 /* metres: a typical blade, for the pixel-size radius */

typedef struct ground_cover_models {
    uint32_t grass_first;  /* first prototype of the grass variants */
    uint32_t herb_first;   /* first prototype of the herb variants */
} ground_cover_models;

/* Adds the two species, their materials and their prototypes to s. Returns 0, or -1 with err
 * set (out of memory). */
int ground_cover_models_add(scene *s, uint64_t seed, ground_cover_models *out, err_buf *err);

#endif
