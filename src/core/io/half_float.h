/* half_float.h — IEEE 754 binary16 ("half") conversion for the EXR writer. float → half rounds
 * to nearest, ties to even; values at or beyond 65520 in magnitude become infinity, values too
 * small for the smallest subnormal (2^-24) become a signed zero, NaN stays NaN. */
#ifndef SYLVA_HALF_FLOAT_H
#define SYLVA_HALF_FLOAT_H

#include <stdint.h>

uint16_t half_from_float(float f);
/* Exact: every half value is a float value. */
float half_to_float(uint16_t h);

#endif
