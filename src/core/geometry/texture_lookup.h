/* texture_lookup.h — nearest-texel lookup with wrapping. Colour channels are stored sRGB-encoded
 * in 8 bits and returned linear; alpha is returned as stored (0..1). Nearest sampling keeps the
 * alpha test exact and identical between camera and shadow rays. */
#ifndef SYLVA_TEXTURE_LOOKUP_H
#define SYLVA_TEXTURE_LOOKUP_H

#include <math.h>

#include "scene/scene.h"

float texture_srgb_to_linear(uint8_t v);

/* The number (row y * width + column x) of the texel of a width x height texture nearest to
 * (u, v). */
static inline size_t texture_texel_index(uint32_t width, uint32_t height, float u, float v)
{
    float fu = u - floorf(u), fv = v - floorf(v);
    uint32_t x = (uint32_t)(fu * width), y = (uint32_t)((1.0f - fv) * height);
    if (x >= width) x = width - 1;
    if (y >= height) y = height - 1;
    return (size_t)y * width + x;
}

/* The 4 stored bytes (sRGB colour, alpha) of the texel nearest to (u, v). */
static inline const uint8_t *texture_texel(const texture *t, float u, float v)
{
    return t->rgba + texture_texel_index(t->width, t->height, u, v) * 4;
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
