/* vessel_math.h — the small 3-D algebra the vessel model needs: vectors and orthonormal frames
 * (3x3 matrices whose columns are a branch's local x, y and z axes in the tree's frame), and
 * rotations about an axis, on the plugins' common vec3.h. Header-only; no state. */
#ifndef VESSEL_MATH_H
#define VESSEL_MATH_H

#include <math.h>

#include "vec3.h"

#define VESSEL_DEG (M_PI / 180.0)

typedef struct vessel_vec {
    double x, y, z;
} vessel_vec;

/* A frame: c[0], c[1], c[2] are the local x, y (the branch axis) and z axes, unit and
 * right-handed, written in the tree's frame. */
typedef struct vessel_frame {
    vessel_vec c[3];
} vessel_frame;

static inline vessel_vec vv(double x, double y, double z) { return (vessel_vec){x, y, z}; }
static inline vessel_vec vv_add(vessel_vec a, vessel_vec b) { return vv(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vessel_vec vv_sub(vessel_vec a, vessel_vec b) { return vv(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vessel_vec vv_scale(vessel_vec a, double s) { return vv(a.x * s, a.y * s, a.z * s); }
static inline vessel_vec vv_madd(vessel_vec a, vessel_vec b, double s)
{
    return vv(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s);
}
/* The products and the length are the plugins' common ones (vec3.h) on the components. */
#define VV_XYZ(a) ((const double[3]){(a).x, (a).y, (a).z})
static inline double vv_dot(vessel_vec a, vessel_vec b) { return vec3_dot(VV_XYZ(a), VV_XYZ(b)); }
static inline vessel_vec vv_cross(vessel_vec a, vessel_vec b)
{
    double c[3];
    vec3_cross(VV_XYZ(a), VV_XYZ(b), c);
    return vv(c[0], c[1], c[2]);
}
static inline double vv_len(vessel_vec a) { return vec3_length(VV_XYZ(a)); }
static inline vessel_vec vv_unit(vessel_vec a)
{
    double l = vv_len(a);
    return l > 0 ? vv_scale(a, 1.0 / l) : a;
}

/* Rodrigues: v rotated by `angle` radians about the unit axis u (right hand). */
static inline vessel_vec vv_rotate(vessel_vec v, vessel_vec u, double angle)
{
    double c = cos(angle), s = sin(angle);
    vessel_vec r = vv_scale(v, c);
    r = vv_madd(r, vv_cross(u, v), s);
    return vv_madd(r, u, vv_dot(u, v) * (1.0 - c));
}

/* A local vector (components along the frame's axes) in the tree's frame. */
static inline vessel_vec frame_to_tree(const vessel_frame *f, vessel_vec local)
{
    vessel_vec r = vv_scale(f->c[0], local.x);
    r = vv_madd(r, f->c[1], local.y);
    return vv_madd(r, f->c[2], local.z);
}

/* A vector of the tree's frame in local components (the transpose: the frame's inverse). */
static inline vessel_vec frame_to_local(const vessel_frame *f, vessel_vec v)
{
    return vv(vv_dot(f->c[0], v), vv_dot(f->c[1], v), vv_dot(f->c[2], v));
}

/* The frame turned by `angle` radians about one of its own axes given in local components
 * (an intrinsic rotation: F' = F R_u(angle)). */
static inline void frame_turn(vessel_frame *f, vessel_vec local_axis, double angle)
{
    if (angle == 0.0) return;
    vessel_vec u = frame_to_tree(f, local_axis);
    for (int k = 0; k < 3; k++) f->c[k] = vv_rotate(f->c[k], u, angle);
}

#endif
