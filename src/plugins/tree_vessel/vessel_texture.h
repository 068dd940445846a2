/* vessel_texture.h — the plugin's bark and leaf textures (t_bark, t_leaf of 004 §3.3), drawn
 * procedurally so that no image file is needed: the bark is the shared fractal bark (003 §1,
 * bark_fractal.h) of the species' `bark:` and `bark_angle:`, the leaf the affine-map leaf of its
 * `leaf:`. Both are RGBA8, sRGB-encoded, row 0 at
 * the top (v = 1). Colour channels hold a grey brightness pattern that the material's albedo
 * multiplies; a leaf's alpha holds its outline (255 inside, 0 outside).
 *
 * The bark is the escape-time pattern of a fixed λ and the leaves come from the chaos game with
 * a fixed seed, not from the scene's random stream: every scene gets the same textures. Bark
 * tiles in u and v; a leaf's stalk is at v = 0 and its tip at v = 1. */
#ifndef VESSEL_TEXTURE_H
#define VESSEL_TEXTURE_H

#include <stdint.h>

#include "vessel_params.h"

#define VESSEL_BARK_TEXTURE_SIZE 128u /* square, one circumference wide and long */
#define VESSEL_LEAF_TEXTURE_SIZE 128u /* square */

/* Fills rgba (VESSEL_BARK_TEXTURE_SIZE^2 * 4 bytes) with the species' bark pattern. */
void vessel_texture_bark(const vessel_params *p, uint8_t *rgba);

#define VESSEL_LEAF_TEXTURE_SEED 1u /* the chaos game's seed: every scene, the same leaves */

#define VESSEL_SPRAY_FAN 90.0  /* degrees between the outermost leaves of a spray */
#define VESSEL_SPRAY_SCALE 0.7  /* each leaf of a spray, over the quad */

/* Fills rgba (VESSEL_LEAF_TEXTURE_SIZE^2 * 4 bytes) with the leaf outline and veins, the
 * attractor of the species' affine maps (leaf_affine.h): one leaf filling the quad, or a spray
 * of leaf_spray smaller ones fanned from the stalk. Returns 0, or -1 when out of memory. */
int vessel_texture_leaf(const vessel_params *p, uint8_t *rgba);

#endif
