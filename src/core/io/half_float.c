/* half_float.c — bit-level float ↔ half conversion; no tables, no floating-point rounding
 * mode dependence. */
#include "io/half_float.h"

#include <string.h>

uint16_t half_from_float(float f)
{
    uint32_t x;
    memcpy(&x, &f, sizeof x);
    uint16_t sign = (uint16_t)((x >> 16) & 0x8000u);
    uint32_t mag = x & 0x7fffffffu;

    if (mag >= 0x7f800000u) {
        if (mag == 0x7f800000u) return sign | 0x7c00u;
        /* NaN: keep the top payload bits and force the quiet bit so the result stays NaN. */
        return sign | 0x7e00u | (uint16_t)((mag >> 13) & 0x3ffu);
    }
    /* 65520 lies halfway between 65504 (largest half) and 65536; ties go to even, i.e. up. */
    if (mag >= 0x477ff000u) return sign | 0x7c00u;

    if (mag >= 0x38800000u) { /* normal half: 2^-14 and above */
        uint32_t h = ((mag >> 23) - 127u + 15u) << 10 | ((mag & 0x7fffffu) >> 13);
        uint32_t rest = mag & 0x1fffu;
        if (rest > 0x1000u || (rest == 0x1000u && (h & 1u))) h++; /* a carry moves the exponent */
        return sign | (uint16_t)h;
    }
    /* 2^-25 is halfway between zero and the smallest subnormal; ties go to even (zero). */
    if (mag <= 0x33000000u) return sign;

    /* subnormal half: value / 2^-24, with the float's implicit leading bit made explicit */
    uint32_t mant = (mag & 0x7fffffu) | 0x800000u;
    uint32_t shift = 126u - (mag >> 23); /* 14 .. 24 */
    uint32_t h = mant >> shift;
    uint32_t rest = mant & ((1u << shift) - 1u);
    uint32_t halfway = 1u << (shift - 1u);
    if (rest > halfway || (rest == halfway && (h & 1u))) h++; /* 0x400 is the smallest normal */
    return sign | (uint16_t)h;
}

float half_to_float(uint16_t h)
{
    uint32_t sign = (uint32_t)(h & 0x8000u) << 16;
    uint32_t exp = (h >> 10) & 0x1fu;
    uint32_t mant = h & 0x3ffu;
    uint32_t x;

    if (exp == 0x1fu) {
        x = sign | 0x7f800000u | (mant << 13);
    } else if (exp != 0) {
        x = sign | ((exp - 15u + 127u) << 23) | (mant << 13);
    } else if (mant == 0) {
        x = sign;
    } else { /* subnormal: normalise the mantissa */
        uint32_t e = 127u - 15u + 1u;
        while (!(mant & 0x400u)) {
            mant <<= 1;
            e--;
        }
        x = sign | (e << 23) | ((mant & 0x3ffu) << 13);
    }
    float f;
    memcpy(&f, &x, sizeof f);
    return f;
}
