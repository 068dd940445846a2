/* aono_angle_law.h — the branching angle φ as a function of the growth level n (seed 000
 * §3.2): a constant, or the linear law (13) through two points, the quadratic (14) fitted by
 * least squares, or the exponential law (15). Angles in degrees. Pure functions, no state.
 */
#ifndef AONO_ANGLE_LAW_H
#define AONO_ANGLE_LAW_H

#include <stddef.h>
#include <stdint.h>

typedef enum aono_law_kind {
    AONO_LAW_CONSTANT = 0,   /* φ = c */
    AONO_LAW_LINEAR = 1,     /* φ = a n + b                      (13) */
    AONO_LAW_QUADRATIC = 2,  /* φ = a n² + b n + c               (14) */
    AONO_LAW_EXPONENTIAL = 3 /* φ = A e^(−B n), A in a, B in b   (15) */
} aono_law_kind;

typedef struct aono_angle_law {
    aono_law_kind kind;
    double a, b, c;
} aono_angle_law;

/* Fits a law of `kind` (not CONSTANT) to n points (n_i, φ_i) given as pairs in xy[2n].
 * LINEAR: exactly two points with different n: a = (φ2 − φ1)/(n2 − n1), b = φ1 − a n1.
 * QUADRATIC: at least three points at three or more different n; least squares.
 * EXPONENTIAL: exactly two points with different n and φ > 0; with n1 = 0 this is (15):
 *   A = φ(0), B = −ln(φ(n2)/A)/n2; otherwise the same curve through both points.
 * Returns 0, or -1 with a sentence in why[why_size] saying what the points lack. */
int aono_law_fit(aono_law_kind kind, const double *xy, uint32_t n, aono_angle_law *out,
                 char *why, size_t why_size);

/* φ(n) in degrees, unclamped. */
double aono_law_eval(const aono_angle_law *law, double n);

#endif
