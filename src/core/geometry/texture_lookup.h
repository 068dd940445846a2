/* texture_lookup.h — nearest-texel lookup with wrapping. Colour channels are stored sRGB-encoded
 * in 8 bits and returned linear; alpha is returned as stored (0..1). Nearest sampling keeps the
 * alpha test exact and identical between camera and shadow rays. */
#ifndef SYLVA_TEXTURE_LOOKUP_H
#define SYLVA_TEXTURE_LOOKUP_H

#include <math.h>

#include "scene/scene.h"

float texture_srgb_to_linear(uint8_t v);

/* The 4 stored bytes (sRGB colour, alpha) of the texel nearest to (u, v). */
static inline const uint8_t *texture_texel(const texture *t, float u, float v)
{
    float fu = u - floorf(u), fv = v - floorf(v);
    uint32_t x = (uint32_t)(fu * t->width), y = (uint32_t)((1.0f - fv) * t->height);
    if (x >= t->width) x = t->width - 1;
    if (y >= t->height) y = t->height - 1;
    return t->rgba + ((size_t)y * t->width + x) * 4;
}

static inline void texture_sample(const texture *t, float u, float v, float rgba[4])
{
    const uint8_t *p = texture_texel(t, u, v);
    rgba[0] = texture_srgb_to_linear(p[0]);
    rgba[1] = texture_srgb_to_linear(p[1]);
    rgba[2] = texture_srgb_to_linear(p[2]);
    rgba[3] = p[3] * (1.0f / 255.0f);
}

#endif
