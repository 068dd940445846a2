/* lsys_palette.h — what colour indices (`c`, `c(x)`) look like: the default palette, after the
 * names of Lparser 2.1's fifteen colours, made into plausible reflectances (linear RGB), and the
 * rules that turn a palette entry into a material.
 *
 * A colour index resolves, in order, to: the scene's `palette` entry for it, the file's `color`
 * line for it (sRGB 0..255, decoded and capped at LSYS_ALBEDO_CAP), the default entry
 * index mod LSYS_PALETTE_SIZE. Segments become Lambertian wood; polygons become two-sided leaves
 * whose transmittance, unless given, is half the albedo (never more than 1 - albedo).
 */
#ifndef LSYS_PALETTE_H
#define LSYS_PALETTE_H

#include <stdint.h>

#define LSYS_PALETTE_SIZE 16
#define LSYS_ALBEDO_CAP 0.9f

/* Linear RGB albedo and the name of default entry index mod LSYS_PALETTE_SIZE. */
void lsys_palette_default(int32_t index, float albedo[3]);
const char *lsys_palette_name(int32_t index);

/* sRGB-encoded component in [0, 1] to linear. */
float lsys_srgb_to_linear(float c);

/* The leaf transmittance that goes with an albedo when none is given. */
void lsys_leaf_transmittance(const float albedo[3], float t[3]);

#endif
