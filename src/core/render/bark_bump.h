/* bark_bump.h — relief on bark: the shading normal of a textured plant surface that is not a
 * leaf (a Lambertian material with a texture and no alpha mask on a species' prototype: the
 * vessel model's bark) is tilted by the gradient of its texture's luminance, read as a height
 * field over the triangle's uv frame (Blinn 1978's bump mapping: with p' = p + h n, the normal
 * of p' is dp/du x dp/dv + h_u (n x dp/dv) + h_v (dp/du x n) to first order in h).
 *
 * The height is BARK_BUMP_SLOPE times the luminance in units of the texel's width along u on
 * the surface, so a luminance step of 1 from one texel to the next tilts the normal by a slope
 * of BARK_BUMP_SLOPE whatever the branch's girth: dark furrows between light plates read as
 * grooves on a trunk and on a twig alike. Luminance differences are central, over
 * BARK_BUMP_REACH texels either side: wide enough to follow a groove's flank rather than the
 * texture's texel-to-texel grain (the lookup is nearest-texel).
 *
 * No black facets: the tilted normal is kept at least BARK_BUMP_MIN_COSINE on the side of the
 * geometric normal where the interpolated normal lies, so the integrator never turns it over.
 * A triangle whose uvs are degenerate keeps its normal. */
#ifndef SYLVA_BARK_BUMP_H
#define SYLVA_BARK_BUMP_H

#include "render/accel_types.h"

#define BARK_BUMP_SLOPE 3.0f
#define BARK_BUMP_MIN_COSINE 0.1f
#define BARK_BUMP_REACH 2.0f /* texels either side of the hit for the luminance difference */

/* Tilts h->ns when h lies on bark (as above) of triangle t of prototype mesh m placed by xf. */
void bark_bump(const scene *s, const mesh *m, uint32_t t, const xform3x4 *xf, hit_info *h);

#endif
