/* wp_frame.h — points, rotations and frames as Arbaro 1.9 computes them (its Vector, Matrix and
 * Transformation): a frame is a rotation matrix and a translation, its columns the frame's
 * axes; the local rotations (rotx, roty, rotz, rotxz, rotaxisz) multiply on the right, the
 * rotation about a global axis (rotaxis) on the left. Angles in degrees. Every sum and product is
 * done in Arbaro's order, so a tree grown with these matches Arbaro's to the last bit or nearly. */
#ifndef WP_FRAME_H
#define WP_FRAME_H

typedef struct wp_vec {
    double x, y, z;
} wp_vec;

typedef struct wp_mat {
    double m[3][3]; /* m[row][column] */
} wp_mat;

typedef struct wp_frame {
    wp_mat rot;
    wp_vec t;
} wp_frame;

static inline wp_vec wp_v(double x, double y, double z)
{
    wp_vec v = { x, y, z };
    return v;
}

static inline wp_vec wp_vadd(wp_vec a, wp_vec b)
{
    return wp_v(a.x + b.x, a.y + b.y, a.z + b.z);
}

/* Arbaro's sub is add(v.mul(-1)): the same numbers as a - b. */
static inline wp_vec wp_vsub(wp_vec a, wp_vec b)
{
    return wp_v(a.x - b.x, a.y - b.y, a.z - b.z);
}

static inline wp_vec wp_vmul(wp_vec a, double f)
{
    return wp_v(a.x * f, a.y * f, a.z * f);
}

/* The inner product, summed x, y, z in that order. */
static inline double wp_vdot(wp_vec a, wp_vec b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

double wp_vabs(wp_vec a);
wp_vec wp_vnormalize(wp_vec a);

/* Arbaro's atan2(v, u): the angle of (u, v) with the u axis in degrees, (-180, 180]. */
double wp_atan2_deg(double v, double u);

/* The identity frame at the origin. */
wp_frame wp_frame_identity(void);

/* The frame's axes: the rotation's columns. */
wp_vec wp_frame_x(const wp_frame *f);
wp_vec wp_frame_y(const wp_frame *f);
wp_vec wp_frame_z(const wp_frame *f);

/* rot * v + t. */
wp_vec wp_frame_apply(const wp_frame *f, wp_vec v);

/* The frame moved by v (in the parent's coordinates). */
wp_frame wp_frame_translate(const wp_frame *f, wp_vec v);

/* Local rotations about the frame's own x, y, z axis by `angle` degrees. */
wp_frame wp_frame_rotx(const wp_frame *f, double angle);
wp_frame wp_frame_roty(const wp_frame *f, double angle);
wp_frame wp_frame_rotz(const wp_frame *f, double angle);

/* Arbaro's rotxz(delta, rho): about z by rho, then about the new x by delta (a child stem's
 * rotation and down angle). */
wp_frame wp_frame_rotxz(const wp_frame *f, double delta, double rho);

/* Arbaro's rotaxisz(delta, rho): away from the local z axis by delta about the axis in the
 * local xy plane at angle rho (splits and random curving). */
wp_frame wp_frame_rotaxisz(const wp_frame *f, double delta, double rho);

/* Rotation by `angle` degrees about the global axis `axis` (normalized here). */
wp_frame wp_frame_rotaxis(const wp_frame *f, double angle, wp_vec axis);

#endif
