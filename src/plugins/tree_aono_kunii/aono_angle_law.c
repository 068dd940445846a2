/* aono_angle_law.c — fitting and evaluating the branching-angle laws (13)–(15) of seed 000.
 * The quadratic least squares solves the 3 x 3 normal equations in a centred, scaled variable
 * so that level numbers far from 0 do not spoil the conditioning. */
#include "aono_angle_law.h"

#include <math.h>
#include <stdio.h>

static int distinct_levels(const double *xy, uint32_t n)
{
    int count = 0;
    for (uint32_t i = 0; i < n; i++) {
        int seen = 0;
        for (uint32_t j = 0; j < i; j++) seen |= xy[2 * j] == xy[2 * i];
        count += !seen;
    }
    return count;
}

static int fit_linear(const double *xy, uint32_t n, aono_angle_law *out, char *why, size_t sz)
{
    if (n != 2) {
        snprintf(why, sz, "the linear law (13) runs through exactly two points (n1, phi1), (n2, phi2); "
                          "got %u", n);
        return -1;
    }
    double n1 = xy[0], p1 = xy[1], n2 = xy[2], p2 = xy[3];
    if (n1 == n2) {
        snprintf(why, sz, "the linear law (13) needs two different levels; both points are at n = %g", n1);
        return -1;
    }
    out->kind = AONO_LAW_LINEAR;
    out->a = (p2 - p1) / (n2 - n1);
    out->b = p1 - out->a * n1;
    out->c = 0.0;
    return 0;
}

/* Solves the symmetric 3 x 3 system m x = r by Gaussian elimination with partial pivoting.
 * Returns -1 when it is singular. */
static int solve3(double m[3][3], double r[3], double x[3])
{
    for (int col = 0; col < 3; col++) {
        int piv = col;
        for (int row = col + 1; row < 3; row++)
            if (fabs(m[row][col]) > fabs(m[piv][col])) piv = row;
        if (!(fabs(m[piv][col]) > 1e-12)) return -1;
        if (piv != col) {
            for (int k = 0; k < 3; k++) {
                double t = m[col][k];
                m[col][k] = m[piv][k], m[piv][k] = t;
            }
            double t = r[col];
            r[col] = r[piv], r[piv] = t;
        }
        for (int row = col + 1; row < 3; row++) {
            double f = m[row][col] / m[col][col];
            for (int k = col; k < 3; k++) m[row][k] -= f * m[col][k];
            r[row] -= f * r[col];
        }
    }
    for (int row = 2; row >= 0; row--) {
        double s = r[row];
        for (int k = row + 1; k < 3; k++) s -= m[row][k] * x[k];
        x[row] = s / m[row][row];
    }
    return 0;
}

static int fit_quadratic(const double *xy, uint32_t n, aono_angle_law *out, char *why, size_t sz)
{
    if (n < 3 || distinct_levels(xy, n) < 3) {
        snprintf(why, sz, "the quadratic law (14) is fitted by least squares to at least three points at "
                          "three different levels; got %u point(s) at %d level(s)",
                 n, n ? distinct_levels(xy, n) : 0);
        return -1;
    }
    /* t = (n − mean) / spread; fit φ = p2 t² + p1 t + p0, then expand back to n. */
    double mean = 0.0, lo = xy[0], hi = xy[0];
    for (uint32_t i = 0; i < n; i++) {
        mean += xy[2 * i];
        lo = fmin(lo, xy[2 * i]), hi = fmax(hi, xy[2 * i]);
    }
    mean /= n;
    double s = 0.5 * (hi - lo);
    double m[3][3] = {{0}}, r[3] = {0}, p[3];
    for (uint32_t i = 0; i < n; i++) {
        double t = (xy[2 * i] - mean) / s, pw[5] = {1, t, t * t, t * t * t, t * t * t * t};
        for (int j = 0; j < 3; j++) {
            for (int k = 0; k < 3; k++) m[j][k] += pw[j + k];
            r[j] += pw[j] * xy[2 * i + 1];
        }
    }
    if (solve3(m, r, p)) {
        snprintf(why, sz, "the quadratic law (14) cannot be fitted to these points (the least-squares "
                          "system is singular)");
        return -1;
    }
    /* φ = p0 + p1 (n − m)/s + p2 (n − m)²/s² */
    out->kind = AONO_LAW_QUADRATIC;
    out->a = p[2] / (s * s);
    out->b = p[1] / s - 2.0 * p[2] * mean / (s * s);
    out->c = p[0] - p[1] * mean / s + p[2] * mean * mean / (s * s);
    return 0;
}

static int fit_exponential(const double *xy, uint32_t n, aono_angle_law *out, char *why, size_t sz)
{
    if (n != 2) {
        snprintf(why, sz, "the exponential law (15) runs through exactly two points (0, phi(0)) and "
                          "(n2, phi(n2)); got %u", n);
        return -1;
    }
    double n1 = xy[0], p1 = xy[1], n2 = xy[2], p2 = xy[3];
    if (n1 == n2) {
        snprintf(why, sz, "the exponential law (15) needs two different levels; both points are at n = %g", n1);
        return -1;
    }
    if (!(p1 > 0.0 && p2 > 0.0)) {
        snprintf(why, sz, "the exponential law (15) needs angles above 0 at both points; got %g and %g "
                          "degrees", p1, p2);
        return -1;
    }
    /* φ = A e^(−B n) through both points; for n1 = 0: A = φ(0), B = −ln(φ(n2)/A)/n2. */
    out->kind = AONO_LAW_EXPONENTIAL;
    out->b = -log(p2 / p1) / (n2 - n1);
    out->a = p1 * exp(out->b * n1);
    out->c = 0.0;
    return 0;
}

int aono_law_fit(aono_law_kind kind, const double *xy, uint32_t n, aono_angle_law *out,
                 char *why, size_t why_size)
{
    switch (kind) {
    case AONO_LAW_LINEAR: return fit_linear(xy, n, out, why, why_size);
    case AONO_LAW_QUADRATIC: return fit_quadratic(xy, n, out, why, why_size);
    case AONO_LAW_EXPONENTIAL: return fit_exponential(xy, n, out, why, why_size);
    default:
        snprintf(why, why_size, "a constant angle is given by fi, not fitted to points");
        return -1;
    }
}

double aono_law_eval(const aono_angle_law *law, double n)
{
    switch (law->kind) {
    case AONO_LAW_LINEAR: return law->a * n + law->b;
    case AONO_LAW_QUADRATIC: return (law->a * n + law->b) * n + law->c;
    case AONO_LAW_EXPONENTIAL: return law->a * exp(-law->b * n);
    default: return law->c;
    }
}
