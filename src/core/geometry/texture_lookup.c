/* texture_lookup.c — the sRGB decoding table. */
#include "geometry/texture_lookup.h"

float texture_srgb_to_linear(uint8_t v)
{
    /* IEC 61966-2-1 decoding, computed once per value on first use is avoided by a direct
     * formula: cheap enough next to a ray cast. */
    float c = v * (1.0f / 255.0f);
    return c <= 0.04045f ? c / 12.92f : powf((c + 0.055f) / 1.055f, 2.4f);
}
