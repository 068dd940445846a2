/* pov_number.c — decimal text for POV-Ray scene files, by integer arithmetic on the scaled
 * value (printf's %g is several times slower and an export prints millions of numbers). */
#include "pov/pov_number.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static const double pow10_exact[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10,
                                     1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18};
static const uint64_t pow10_int[] = {1ull, 10ull, 100ull, 1000ull, 10000ull, 100000ull, 1000000ull,
                                     10000000ull, 100000000ull, 1000000000ull, 10000000000ull,
                                     100000000000ull, 1000000000000ull, 10000000000000ull,
                                     100000000000000ull, 1000000000000000ull, 10000000000000000ull,
                                     100000000000000000ull, 1000000000000000000ull};

#define PLAIN_MIN 1e-5
#define PLAIN_MAX 1e9

/* floor(log10(a)) for a in [PLAIN_MIN, PLAIN_MAX). */
static int decimal_exponent(double a)
{
    int e = 0;
    if (a >= 1.0) {
        while (e < 8 && a >= pow10_exact[e + 1]) e++;
    } else {
        e = -1;
        while (e > -5 && a * pow10_exact[-e] < 1.0) e--;
    }
    return e;
}

/* Writes n / 10^dec with the fraction's trailing zeros dropped. */
static int emit_scaled(char *buf, int negative, uint64_t n, int dec)
{
    char digits[24];
    int len = 0;
    uint64_t whole = n / pow10_int[dec], frac = n % pow10_int[dec];
    while (dec > 0 && frac % 10 == 0) frac /= 10, dec--;
    char *p = buf;
    if (negative && (whole || frac)) *p++ = '-';
    do {
        digits[len++] = (char)('0' + whole % 10);
        whole /= 10;
    } while (whole);
    while (len) *p++ = digits[--len];
    if (dec > 0) {
        *p++ = '.';
        for (int k = dec - 1; k >= 0; k--) {
            p[k] = (char)('0' + frac % 10);
            frac /= 10;
        }
        p += dec;
    }
    *p = '\0';
    return (int)(p - buf);
}

static int scale_digits(int digits, int e)
{
    int dec = digits - 1 - e;
    return dec < 0 ? 0 : dec;
}

int pov_format_real(char *buf, double v, int digits)
{
    if (!isfinite(v)) {
        memcpy(buf, "0", 2);
        return -1;
    }
    if (digits < 1) digits = 1;
    if (digits > 9) digits = 9;
    double a = fabs(v);
    if (a == 0.0) {
        memcpy(buf, "0", 2);
        return 1;
    }
    if (a < PLAIN_MIN || a >= PLAIN_MAX) return snprintf(buf, POV_NUMBER_MAX, "%.*g", digits, v);
    int dec = scale_digits(digits, decimal_exponent(a));
    uint64_t n = (uint64_t)(a * pow10_exact[dec] + 0.5);
    return emit_scaled(buf, v < 0.0, n, dec);
}

int pov_format_float(char *buf, float f)
{
    if (!isfinite(f)) {
        memcpy(buf, "0", 2);
        return -1;
    }
    double a = fabs((double)f);
    if (a == 0.0) {
        memcpy(buf, "0", 2);
        return 1;
    }
    if (a < PLAIN_MIN || a >= PLAIN_MAX) return snprintf(buf, POV_NUMBER_MAX, "%.9g", (double)f);
    int e = decimal_exponent(a);
    for (int digits = 1; digits <= 9; digits++) {
        int dec = scale_digits(digits, e);
        uint64_t n = (uint64_t)(a * pow10_exact[dec] + 0.5);
        if ((float)((double)n / pow10_exact[dec]) == (float)a) return emit_scaled(buf, f < 0.0f, n, dec);
    }
    return snprintf(buf, POV_NUMBER_MAX, "%.9g", (double)f);
}

int pov_format_position(char *buf, float f)
{
    int len = pov_format_float(buf, f);
    double a = fabs((double)f);
    if (len < 0 || a < PLAIN_MIN || a >= PLAIN_MAX) return len;
    /* the value of the shortest text, from its digits as pov_format_float chose them */
    int e = decimal_exponent(a);
    for (int digits = 1; digits <= 9; digits++) {
        int dec = scale_digits(digits, e);
        uint64_t n = (uint64_t)(a * pow10_exact[dec] + 0.5);
        if ((float)((double)n / pow10_exact[dec]) != (float)a) continue;
        if (fabs((double)n / pow10_exact[dec] - a) <= POV_POSITION_TOLERANCE) return len;
        break;
    }
    return emit_scaled(buf, f < 0.0f, (uint64_t)(a * pow10_exact[6] + 0.5), 6);
}
