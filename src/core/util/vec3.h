/* vec3.h — small float vector and 3x4 affine transform arithmetic, all inline. Right-handed,
 * Z up. A xform3x4 maps p to (M p + t); m[r][c] with the translation in column 3. */
#ifndef SYLVA_VEC3_H
#define SYLVA_VEC3_H

#include <math.h>

typedef struct vec3 {
    float x, y, z;
} vec3;

typedef struct xform3x4 {
    float m[3][4];
} xform3x4;

static inline vec3 v3(float x, float y, float z) { return (vec3){x, y, z}; }
static inline vec3 v3_add(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec3 v3_sub(vec3 a, vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3 v3_mul(vec3 a, vec3 b) { return v3(a.x * b.x, a.y * b.y, a.z * b.z); }
static inline vec3 v3_scale(vec3 a, float s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline vec3 v3_madd(vec3 a, vec3 b, float s) { return v3(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s); }
static inline float v3_dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline vec3 v3_cross(vec3 a, vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline float v3_len(vec3 a) { return sqrtf(v3_dot(a, a)); }
static inline vec3 v3_norm(vec3 a)
{
    float l = v3_len(a);
    return l > 0.0f ? v3_scale(a, 1.0f / l) : a;
}
static inline float v3_max(vec3 a) { return fmaxf(a.x, fmaxf(a.y, a.z)); }
static inline float v3_luminance(vec3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

/* An orthonormal basis (t, b, n) around unit n (Duff et al. 2017, branchless). */
static inline void v3_basis(vec3 n, vec3 *t, vec3 *b)
{
    float sign = copysignf(1.0f, n.z);
    float a = -1.0f / (sign + n.z);
    float c = n.x * n.y * a;
    *t = v3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
    *b = v3(c, sign + n.y * n.y * a, -n.y);
}

static inline xform3x4 xf_identity(void)
{
    return (xform3x4){{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};
}
static inline vec3 xf_point(const xform3x4 *x, vec3 p)
{
    return v3(x->m[0][0] * p.x + x->m[0][1] * p.y + x->m[0][2] * p.z + x->m[0][3],
              x->m[1][0] * p.x + x->m[1][1] * p.y + x->m[1][2] * p.z + x->m[1][3],
              x->m[2][0] * p.x + x->m[2][1] * p.y + x->m[2][2] * p.z + x->m[2][3]);
}
static inline vec3 xf_vector(const xform3x4 *x, vec3 v)
{
    return v3(x->m[0][0] * v.x + x->m[0][1] * v.y + x->m[0][2] * v.z,
              x->m[1][0] * v.x + x->m[1][1] * v.y + x->m[1][2] * v.z,
              x->m[2][0] * v.x + x->m[2][1] * v.y + x->m[2][2] * v.z);
}
/* Transforms a normal by the inverse transpose of the linear part (cofactor matrix; the
 * determinant's scale is dropped because the result is normalised by the caller). */
static inline vec3 xf_normal(const xform3x4 *x, vec3 n)
{
    const float(*m)[4] = x->m;
    float c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1], c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2],
          c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    float c10 = m[0][2] * m[2][1] - m[0][1] * m[2][2], c11 = m[0][0] * m[2][2] - m[0][2] * m[2][0],
          c12 = m[0][1] * m[2][0] - m[0][0] * m[2][1];
    float c20 = m[0][1] * m[1][2] - m[0][2] * m[1][1], c21 = m[0][2] * m[1][0] - m[0][0] * m[1][2],
          c22 = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    float det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
    vec3 r = v3(c00 * n.x + c01 * n.y + c02 * n.z, c10 * n.x + c11 * n.y + c12 * n.z,
                c20 * n.x + c21 * n.y + c22 * n.z);
    return det < 0.0f ? v3_scale(r, -1.0f) : r;
}
/* a then b: returns b * a. */
static inline xform3x4 xf_compose(const xform3x4 *b, const xform3x4 *a)
{
    xform3x4 r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) {
            r.m[i][j] = b->m[i][0] * a->m[0][j] + b->m[i][1] * a->m[1][j] + b->m[i][2] * a->m[2][j];
            if (j == 3) r.m[i][j] += b->m[i][3];
        }
    return r;
}
/* Translation t, rotation by Euler angles (degrees) about X, then Y, then Z, scale s. */
static inline xform3x4 xf_trs(vec3 t, vec3 rot_deg, vec3 s)
{
    const float d = (float)(M_PI / 180.0);
    float cx = cosf(rot_deg.x * d), sx = sinf(rot_deg.x * d);
    float cy = cosf(rot_deg.y * d), sy = sinf(rot_deg.y * d);
    float cz = cosf(rot_deg.z * d), sz = sinf(rot_deg.z * d);
    /* R = Rz * Ry * Rx */
    float r[3][3] = {{cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx},
                     {sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx},
                     {-sy, cy * sx, cy * cx}};
    xform3x4 x;
    for (int i = 0; i < 3; i++) {
        x.m[i][0] = r[i][0] * s.x;
        x.m[i][1] = r[i][1] * s.y;
        x.m[i][2] = r[i][2] * s.z;
    }
    x.m[0][3] = t.x, x.m[1][3] = t.y, x.m[2][3] = t.z;
    return x;
}

#endif
