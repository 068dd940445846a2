/* lsys_leaf_uv.c — a leaf polygon's texture coordinates in its own frame (stalk at the first
 * vertex, tip along the long axis). Pure function of its arguments. */
#include "lsys_leaf_uv.h"

#include <math.h>

#include "vec3.h"

static void fill(uint32_t n, float *uv)
{
    for (uint32_t i = 0; i < 2 * n; i++) uv[i] = 0.5f;
}

void lsys_leaf_uv(const double *xyz, uint32_t n, const double normal[3], float *uv)
{
    const double *p0 = xyz;
    /* The tip: the vertex farthest from the stalk (the first one on a tie). Every difference
     * from the stalk is divided by the largest coordinate difference, so that no square
     * overflows however far out the model is drawn. */
    double big = 0;
    for (uint32_t i = 1; i < n; i++)
        for (int k = 0; k < 3; k++) big = fmax(big, fabs(xyz[3 * i + k] - p0[k]));
    if (!(big > 0) || !isfinite(big)) {
        fill(n, uv);
        return;
    }
    uint32_t tip = 0;
    double far = -1;
    for (uint32_t i = 1; i < n; i++) {
        double d[3] = {(xyz[3 * i] - p0[0]) / big, (xyz[3 * i + 1] - p0[1]) / big, (xyz[3 * i + 2] - p0[2]) / big};
        double d2 = vec3_dot(d, d);
        if (d2 > far) far = d2, tip = i;
    }
    double y[3] = {xyz[3 * tip] - p0[0], xyz[3 * tip + 1] - p0[1], xyz[3 * tip + 2] - p0[2]};
    if (vec3_normalize_scaled(y)) {
        fill(n, uv);
        return;
    }
    double along = vec3_dot(y, normal);
    for (int k = 0; k < 3; k++) y[k] -= along * normal[k];
    if (vec3_normalize_scaled(y)) {
        fill(n, uv);
        return;
    }
    double x[3];
    vec3_cross(y, normal, x);
    if (vec3_normalize_scaled(x)) {
        fill(n, uv);
        return;
    }
    double bmin = 0, bmax = 0, amax = 0;
    for (uint32_t i = 0; i < n; i++) {
        double d[3] = {(xyz[3 * i] - p0[0]) / big, (xyz[3 * i + 1] - p0[1]) / big, (xyz[3 * i + 2] - p0[2]) / big};
        double a = vec3_dot(d, x), b = vec3_dot(d, y);
        bmin = fmin(bmin, b), bmax = fmax(bmax, b), amax = fmax(amax, fabs(a));
    }
    if (!(bmax > bmin) || !isfinite(bmax - bmin) || !isfinite(amax)) {
        fill(n, uv);
        return;
    }
    for (uint32_t i = 0; i < n; i++) {
        double d[3] = {(xyz[3 * i] - p0[0]) / big, (xyz[3 * i + 1] - p0[1]) / big, (xyz[3 * i + 2] - p0[2]) / big};
        double a = vec3_dot(d, x), b = vec3_dot(d, y);
        uv[2 * i] = (float)(amax > 0 ? 0.5 + 0.5 * a / amax : 0.5);
        uv[2 * i + 1] = (float)((b - bmin) / (bmax - bmin));
    }
}
