/* wp_java.h — the few places where Java's arithmetic differs from C's and Arbaro relies on it:
 * narrowing a double to an int (toward zero, NaN to 0, values past the int range held at its
 * ends, where C is undefined) and Math.min / Math.max (NaN wins, where fmin and fmax drop it). */
#ifndef WP_JAVA_H
#define WP_JAVA_H

#include <limits.h>

static inline int wp_java_int(double x)
{
    if (x != x) return 0;
    if (x >= (double)INT_MAX) return INT_MAX;
    if (x <= (double)INT_MIN) return INT_MIN;
    return (int)x;
}

static inline double wp_java_max(double a, double b)
{
    if (a != a || b != b) return a + b; /* NaN */
    return a >= b ? a : b;
}

static inline double wp_java_min(double a, double b)
{
    if (a != a || b != b) return a + b;
    return a <= b ? a : b;
}

#endif
