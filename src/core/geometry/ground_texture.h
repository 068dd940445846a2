/* ground_texture.h — the ground's colour and micro-relief at any point: the cover weights
 * (ground_cover.h) turned into an albedo with texture at several scales and a relief gradient,
 * evaluated in world space and filtered by a footprint (docs/models/ground.md). The renderer
 * shades terrain hits with it (render/ground_shade.h); the POV-Ray export writes its colour
 * filtered at an image texel (pov/pov_ground.h).
 *
 * Each kind has a mean albedo (the terrain's class albedos for meadow, dry grass, scree, rock and
 * snow; measured values for leaf litter, bare soil and wet ground) varied by octaves of gradient
 * noise from kilometres to centimetres (util/gradient_noise.h), and a micro-relief of its own.
 * Octaves finer than the footprint fade to their mean, so far ground neither aliases into noise
 * nor changes its mean colour.
 *
 * Ownership: a ground_texture owns its cover map and borrows the scene (which must outlive it).
 */
#ifndef SYLVA_GROUND_TEXTURE_H
#define SYLVA_GROUND_TEXTURE_H

#include "geometry/ground_cover.h"
#include "util/vec3.h"

typedef struct ground_texture {
    ground_cover_map *map;       /* owned */
    const sylva_heightfield *hf; /* the scene's terrain; borrowed */
    vec3 albedo[GROUND_KINDS];   /* mean linear RGB albedo of each kind */
    vec3 dry_grass;              /* the meadow's albedo where it is dry */
    vec3 moss, wet_soil, lichen; /* the tints of litter, soil and rock (the terrain's palette) */
    vec3 beyond;                 /* the image's colour beyond the footprint (the mean of 64 x 64
                                    of its texels, decoded) */
} ground_texture;

/* The texture of scene s's ground into *out: NULL when the terrain keeps its materials
 * (ground_cover_map_new), else one the caller frees with ground_texture_free. Returns 0, or -1
 * with err set when memory runs out. */
int ground_texture_build(const scene *s, ground_texture **out, err_buf *err);
void ground_texture_free(ground_texture *g); /* accepts NULL */

#define GROUND_TEXTURE_MAX_TEXELS 1024u /* along the footprint's longer side of the ground image */

/* The ground's image over heightfield hf's footprint, as the POV-Ray export writes it and the
 * verification mode shows it: iw x ih texels of texel metres (the colour filtered at the
 * texel, 8-bit sRGB), row 0 along the northern edge. */
void ground_texture_image_size(const sylva_heightfield *hf, uint32_t *iw, uint32_t *ih, double *texel);

/* Texel (c, r) of that image, 8-bit sRGB into rgb. */
void ground_texture_image_texel(const ground_texture *g, uint32_t c, uint32_t r, uint8_t rgb[3]);

/* That whole image written to path (a PNG, or what its extension names). Returns 0, or -1 with
 * err set. */
int ground_texture_write_image(const ground_texture *g, const char *path, err_buf *err);

/* The image's colour (linear RGB) at map point (x, y): bilinear between the texels' centres (as
 * POV-Ray's image_map with interpolate 2), the edge texels' between the outermost centres and
 * the footprint's edge, and `beyond` outside the footprint (the apron). */
vec3 ground_texture_image_albedo(const ground_texture *g, double x, double y);

/* Albedo (linear RGB) at map point (x, y) seen with footprint (metres), given the weights there. */
vec3 ground_texture_albedo(const ground_texture *g, double x, double y, double footprint,
                           const float w[GROUND_KINDS]);

/* Gradient of the micro-relief at (x, y) (metres per metre, east and north) seen with footprint,
 * given the weights there: the tilt the shading normal takes. */
void ground_texture_relief(const ground_texture *g, double x, double y, double footprint,
                           const float w[GROUND_KINDS], float grad[2]);

#endif
