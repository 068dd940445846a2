/* lsys_texture.h — the textures of an L-system plant: the shared fractal bark (bark_fractal.h)
 * on its tubes and the shared affine-map leaf (leaf_affine.h) on its leaf polygons, one preset
 * of each per species, named by the keys `bark` and `leaf`.
 *
 * The leaf texture keeps the affine leaf's colour (blade, midrib, veins, mottling) over the
 * whole square and is opaque everywhere: the grammar's polygon is the leaf's outline, so the
 * affine leaf's own outline (its alpha) is not used. Both textures are grey (sRGB-encoded
 * RGBA8, row 0 at the top) for the colour index's albedo to multiply. Pure functions of the
 * preset: the same bytes every run. */
#ifndef LSYS_TEXTURE_H
#define LSYS_TEXTURE_H

#include <stdint.h>

#define LSYS_BARK_TEXTURE_SIZE 128u /* square: one turn round the branch, one tile along it */
#define LSYS_LEAF_TEXTURE_SIZE 128u /* square: u across the leaf, v from stalk to tip */
#define LSYS_LEAF_TEXTURE_SEED 1u   /* the chaos game's seed: every scene, the same leaves */

/* The choices of the keys, NULL-terminated; the last real choice is "off" (no texture). */
extern const char *const lsys_bark_texture_names[];
extern const char *const lsys_leaf_texture_names[];

/* Index of "off" in each list. */
#define LSYS_BARK_TEXTURE_OFF 4
#define LSYS_LEAF_TEXTURE_OFF 5

/* Fills rgba (LSYS_BARK_TEXTURE_SIZE^2 * 4 bytes) with the bark of choice `bark` (an index into
 * lsys_bark_texture_names other than "off"); height is caller-owned scratch of
 * LSYS_BARK_TEXTURE_SIZE^2 floats. */
void lsys_texture_bark(int bark, float *height, uint8_t *rgba);

/* Fills rgba (LSYS_LEAF_TEXTURE_SIZE^2 * 4 bytes) with the leaf of choice `leaf` (an index into
 * lsys_leaf_texture_names other than "off"), alpha 255 everywhere. Returns 0, or -1 when out of
 * memory. */
int lsys_texture_leaf(int leaf, uint8_t *rgba);

#endif
