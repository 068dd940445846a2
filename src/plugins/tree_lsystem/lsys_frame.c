/* lsys_frame.c — the turtle's rotations: 001 Table 2 (R_U, R_L, R_H right-multiplying the frame
 * [H L U]), `$` (001 eq. 2) and tropism (001 eq. 3). */
#include <math.h>

#include "lsys_turtle.h"

static void cross(const double a[3], const double b[3], double out[3])
{
    double x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2], z = a[0] * b[1] - a[1] * b[0];
    out[0] = x, out[1] = y, out[2] = z;
}

/* (a, b) <- (c a + s b, -s a + c b): the two columns a rotation matrix of 001 mixes. */
static void mix(double a[3], double b[3], double c, double s)
{
    for (int k = 0; k < 3; k++) {
        double x = a[k], y = b[k];
        a[k] = c * x + s * y;
        b[k] = -s * x + c * y;
    }
}

void lsys_frame_turn(lsys_frame *f, double a)
{
    /* R_U(a) = [[cos a, sin a, 0], [-sin a, cos a, 0], [0, 0, 1]]:
     * H' = H cos a - L sin a, L' = H sin a + L cos a. */
    mix(f->h, f->l, cos(a), -sin(a));
}

void lsys_frame_pitch(lsys_frame *f, double a)
{
    /* R_L(a) = [[cos a, 0, -sin a], [0, 1, 0], [sin a, 0, cos a]]:
     * H' = H cos a + U sin a, U' = -H sin a + U cos a. */
    mix(f->h, f->u, cos(a), sin(a));
}

void lsys_frame_roll(lsys_frame *f, double a)
{
    /* R_H(a) = [[1, 0, 0], [0, cos a, -sin a], [0, sin a, cos a]]:
     * L' = L cos a + U sin a, U' = -L sin a + U cos a. */
    mix(f->l, f->u, cos(a), sin(a));
}

void lsys_frame_roll_horizontal(lsys_frame *f)
{
    static const double v[3] = {0.0, 0.0, -1.0};
    double l[3];
    cross(v, f->h, l);
    double len = sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
    if (len < 1e-12) return;
    for (int k = 0; k < 3; k++) f->l[k] = l[k] / len;
    cross(f->h, f->l, f->u);
}

/* Rotates v about the unit axis k by angle a (Rodrigues). */
static void rotate_about(double v[3], const double k[3], double c, double s)
{
    double kv[3];
    cross(k, v, kv);
    double d = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
    for (int i = 0; i < 3; i++) v[i] = v[i] * c + kv[i] * s + k[i] * d * (1.0 - c);
}

void lsys_frame_tropism(lsys_frame *f, double e)
{
    static const double t[3] = {0.0, 0.0, -1.0};
    double axis[3];
    cross(f->h, t, axis);
    double len = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    if (len < 1e-12) return;
    for (int k = 0; k < 3; k++) axis[k] /= len;
    double a = e * len, c = cos(a), s = sin(a);
    rotate_about(f->h, axis, c, s);
    rotate_about(f->l, axis, c, s);
    rotate_about(f->u, axis, c, s);
}
