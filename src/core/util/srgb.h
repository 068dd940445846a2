/* srgb.h — the sRGB transfer function (IEC 61966-2-1) both ways: textures and photographs are
 * decoded into linear light with it, PNGs, POV-Ray's texture images and photomontages encoded
 * with it. The one place that writes its constants. */
#ifndef SYLVA_SRGB_H
#define SYLVA_SRGB_H

#include <math.h>
#include <stdint.h>

/* Linear value of an encoded one in [0, 1]: linear below 0.04045, a 2.4 power above. */
static inline float srgb_to_linear(float v)
{
    return v <= 0.04045f ? v / 12.92f : powf((v + 0.055f) / 1.055f, 2.4f);
}

/* Encoded value of a linear one in [0, 1]. */
static inline float srgb_from_linear(float v)
{
    return v <= 0.0031308f ? 12.92f * v : 1.055f * powf(v, 1.0f / 2.4f) - 0.055f;
}

/* An 8-bit encoded sample of a linear value, clamped to [0, 1] (NaN as 0). */
static inline uint8_t srgb8_from_linear(float v)
{
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 255;
    return (uint8_t)lrintf(srgb_from_linear(v) * 255.0f);
}

#endif
