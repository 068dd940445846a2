/* vec3.h — the small vector algebra the plugins' models share, on double[3]: dot and cross
 * products, length, the largest component, division by a number and normalisation (plain, and
 * scaled first for vectors of any finite size). Header-only, static inline, no state. */
#ifndef PLUGIN_VEC3_H
#define PLUGIN_VEC3_H

#include <math.h>

static inline double vec3_dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* out = a x b; out may be a or b. */
static inline void vec3_cross(const double a[3], const double b[3], double out[3])
{
    double x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2], z = a[0] * b[1] - a[1] * b[0];
    out[0] = x, out[1] = y, out[2] = z;
}

static inline double vec3_length(const double v[3]) { return sqrt(vec3_dot(v, v)); }

/* The largest absolute component (NaN components are passed over). */
static inline double vec3_largest(const double v[3]) { return fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2]))); }

/* v <- v / s, component by component. */
static inline void vec3_div(double v[3], double s) { v[0] /= s, v[1] /= s, v[2] /= s; }

/* v <- v / |v|. Returns 0, or -1 (v unchanged) when |v| is not above `tiny` (zero, NaN). */
static inline int vec3_normalize(double v[3], double tiny)
{
    double l = vec3_length(v);
    if (!(l > tiny)) return -1;
    vec3_div(v, l);
    return 0;
}

/* v <- v / |v| for a vector of any finite size: scaled by its largest component first, so that
 * the squared length can neither overflow nor underflow. Returns 0, or -1 (v unchanged) when v
 * has no direction (zero) or its largest component is not finite. */
static inline int vec3_normalize_scaled(double v[3])
{
    double big = vec3_largest(v);
    if (!(big > 0) || !isfinite(big)) return -1;
    vec3_div(v, big);
    vec3_div(v, vec3_length(v));
    return 0;
}

#endif
