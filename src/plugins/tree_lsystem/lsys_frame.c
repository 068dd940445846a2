/* lsys_frame.c — the turtle's rotations as Lapré's Lparser 2.1 performs them: each command turns
 * two of the frame's vectors about the third (taken as it stands, unit or not) and then rescales
 * the two to unit length; `$` and `t` as Lparser defines them. */
#include <math.h>

#include "lsys_turtle.h"
#include "vec3.h"

/* v <- (cos a I + sin a [n]x + (1 - cos a) n n^T) v: a right-handed rotation by a about n when n
 * is a unit vector; about a shorter n the turn is smaller (the matrix Lparser builds). */
static void rotate(double v[3], const double n[3], double c, double s)
{
    double nv[3];
    vec3_cross(n, v, nv);
    double d = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
    for (int k = 0; k < 3; k++) v[k] = c * v[k] + s * nv[k] + (1.0 - c) * n[k] * d;
}

/* Rotates a and b by angle about axis, then makes both unit. */
static void rotate_pair(double a[3], double b[3], const double axis[3], double angle)
{
    double n[3] = {axis[0], axis[1], axis[2]};
    double c = cos(angle), s = sin(angle);
    rotate(a, n, c, s);
    rotate(b, n, c, s);
    vec3_normalize(a, 0.0);
    vec3_normalize(b, 0.0);
}

void lsys_frame_turn(lsys_frame *f, double a) { rotate_pair(f->h, f->l, f->u, -a); }

void lsys_frame_pitch(lsys_frame *f, double a) { rotate_pair(f->h, f->u, f->l, a); }

void lsys_frame_roll(lsys_frame *f, double a) { rotate_pair(f->l, f->u, f->h, -a); }

void lsys_frame_roll_horizontal(lsys_frame *f)
{
    static const double sky[3] = {0.0, 0.0, 1.0};
    if (f->h[0] == 0.0 && f->h[1] == 0.0) return;
    /* L = Z x H and U = H x L: U's z is |H_xy|^2, so U points up for any heading not vertical */
    vec3_cross(sky, f->h, f->l);
    vec3_cross(f->h, f->l, f->u);
}

void lsys_frame_tropism(lsys_frame *f, double e)
{
    double hxy = sqrt(f->h[0] * f->h[0] + f->h[1] * f->h[1]);
    if (hxy == 0.0) return;
    lsys_frame_pitch(f, e * hxy);
}
