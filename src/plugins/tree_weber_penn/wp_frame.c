/* wp_frame.c — Arbaro's frame algebra (wp_frame.h). Matrix products sum the three terms of a
 * row times a column left to right, angles become radians as angle * pi / 180, as Arbaro's Java
 * does; changing either changes the last bits and, through the random draws that depend on them,
 * sometimes a whole branch. */
#include "wp_frame.h"

#include <math.h>

double wp_vabs(wp_vec a)
{
    return sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
}

wp_vec wp_vnormalize(wp_vec a)
{
    double len = wp_vabs(a);
    return wp_v(a.x / len, a.y / len, a.z / len);
}

double wp_atan2_deg(double v, double u)
{
    if (u == 0) return v >= 0 ? 90 : -90;
    if (u > 0) return atan(v / u) * 180 / M_PI;
    if (v >= 0) return 180 + atan(v / u) * 180 / M_PI;
    return atan(v / u) * 180 / M_PI - 180;
}

wp_frame wp_frame_identity(void)
{
    wp_frame f = { { { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } } }, { 0, 0, 0 } };
    return f;
}

static wp_vec column(const wp_mat *a, int c)
{
    return wp_v(a->m[0][c], a->m[1][c], a->m[2][c]);
}

wp_vec wp_frame_x(const wp_frame *f)
{
    return column(&f->rot, 0);
}

wp_vec wp_frame_y(const wp_frame *f)
{
    return column(&f->rot, 1);
}

wp_vec wp_frame_z(const wp_frame *f)
{
    return column(&f->rot, 2);
}

static wp_vec mat_apply(const wp_mat *a, wp_vec v)
{
    return wp_v(a->m[0][0] * v.x + a->m[0][1] * v.y + a->m[0][2] * v.z,
                a->m[1][0] * v.x + a->m[1][1] * v.y + a->m[1][2] * v.z,
                a->m[2][0] * v.x + a->m[2][1] * v.y + a->m[2][2] * v.z);
}

static wp_mat mat_product(const wp_mat *a, const wp_mat *b)
{
    wp_mat p;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            p.m[r][c] = a->m[r][0] * b->m[0][c] + a->m[r][1] * b->m[1][c] + a->m[r][2] * b->m[2][c];
    return p;
}

static wp_mat mat_rows(double xx, double xy, double xz, double yx, double yy, double yz, double zx, double zy,
                       double zz)
{
    wp_mat a = { { { xx, xy, xz }, { yx, yy, yz }, { zx, zy, zz } } };
    return a;
}

/* The frame with rotation rot * local, same translation. */
static wp_frame rotate_local(const wp_frame *f, wp_mat local)
{
    wp_frame g = { mat_product(&f->rot, &local), f->t };
    return g;
}

wp_vec wp_frame_apply(const wp_frame *f, wp_vec v)
{
    return wp_vadd(mat_apply(&f->rot, v), f->t);
}

wp_frame wp_frame_translate(const wp_frame *f, wp_vec v)
{
    wp_frame g = { f->rot, wp_vadd(f->t, v) };
    return g;
}

static double radians(double degrees)
{
    return degrees * M_PI / 180;
}

wp_frame wp_frame_rotz(const wp_frame *f, double angle)
{
    double a = radians(angle);
    return rotate_local(f, mat_rows(cos(a), -sin(a), 0, sin(a), cos(a), 0, 0, 0, 1));
}

wp_frame wp_frame_roty(const wp_frame *f, double angle)
{
    double a = radians(angle);
    return rotate_local(f, mat_rows(cos(a), 0, -sin(a), 0, 1, 0, sin(a), 0, cos(a)));
}

wp_frame wp_frame_rotx(const wp_frame *f, double angle)
{
    double a = radians(angle);
    return rotate_local(f, mat_rows(1, 0, 0, 0, cos(a), -sin(a), 0, sin(a), cos(a)));
}

wp_frame wp_frame_rotxz(const wp_frame *f, double delta, double rho)
{
    double d = radians(delta), r = radians(rho);
    double sir = sin(r), cor = cos(r), sid = sin(d), cod = cos(d);
    return rotate_local(f, mat_rows(cor, -sir * cod, sir * sid, sir, cor * cod, -cor * sid, 0, sid, cod));
}

wp_frame wp_frame_rotaxisz(const wp_frame *f, double delta, double rho)
{
    double d = radians(delta), r = radians(rho);
    double a = cos(r), b = sin(r), si = sin(d), co = cos(d);
    return rotate_local(f, mat_rows(co + a * a * (1 - co), b * a * (1 - co), b * si,
                                    a * b * (1 - co), co + b * b * (1 - co), -a * si,
                                    -b * si, a * si, co));
}

wp_frame wp_frame_rotaxis(const wp_frame *f, double angle, wp_vec axis)
{
    double g = radians(angle);
    wp_vec n = wp_vnormalize(axis);
    double a = n.x, b = n.y, c = n.z, si = sin(g), co = cos(g);
    wp_mat r = mat_rows(co + a * a * (1 - co), -c * si + b * a * (1 - co), b * si + c * a * (1 - co),
                        c * si + a * b * (1 - co), co + b * b * (1 - co), -a * si + c * b * (1 - co),
                        -b * si + a * c * (1 - co), a * si + b * c * (1 - co), co + c * c * (1 - co));
    wp_frame h = { mat_product(&r, &f->rot), f->t };
    return h;
}
