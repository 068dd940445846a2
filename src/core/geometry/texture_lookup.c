/* texture_lookup.c — the decoding of 8-bit sRGB texels. */
#include "geometry/texture_lookup.h"

#include "util/srgb.h"

float texture_srgb_to_linear(uint8_t v)
{
    /* a direct formula, cheap enough next to a ray cast */
    return srgb_to_linear(v * (1.0f / 255.0f));
}
