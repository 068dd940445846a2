/* polygon_fill.c — ear clipping: the outline is projected onto the coordinate plane most
 * facing its Newell normal and made counter-clockwise there; a vertex is an ear when its
 * corner is convex and no other remaining vertex lies inside the corner's triangle. */
#include "polygon_fill.h"

#include <math.h>

static double cross2(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* p inside or on triangle abc (counter-clockwise). */
static int in_triangle(const double *p, const double *a, const double *b, const double *c)
{
    return cross2(a, b, p) >= 0 && cross2(b, c, p) >= 0 && cross2(c, a, p) >= 0;
}

uint32_t polygon_fill(const double *xyz, uint32_t n, uint32_t *tri, double normal[3], double *xy,
                      uint32_t *idx)
{
    double nx = 0, ny = 0, nz = 0;
    for (uint32_t i = 0; i < n; i++) {
        const double *p = xyz + 3 * i, *q = xyz + 3 * ((i + 1) % n);
        nx += (p[1] - q[1]) * (p[2] + q[2]);
        ny += (p[2] - q[2]) * (p[0] + q[0]);
        nz += (p[0] - q[0]) * (p[1] + q[1]);
    }
    double len = sqrt(nx * nx + ny * ny + nz * nz);
    normal[0] = normal[1] = normal[2] = 0.0;
    if (n < 3 || !(len > 0) || !isfinite(len)) return 0;
    normal[0] = nx / len, normal[1] = ny / len, normal[2] = nz / len;
    /* Project by dropping the dominant axis; keep the projection counter-clockwise. */
    int drop = fabs(nx) > fabs(ny) ? (fabs(nx) > fabs(nz) ? 0 : 2) : (fabs(ny) > fabs(nz) ? 1 : 2);
    int a0 = (drop + 1) % 3, a1 = (drop + 2) % 3;
    double flip = normal[drop] < 0 ? -1.0 : 1.0;
    for (uint32_t i = 0; i < n; i++) {
        xy[2 * i] = xyz[3 * i + a0];
        xy[2 * i + 1] = flip * xyz[3 * i + a1];
        idx[i] = i;
    }
    uint32_t m = n, t = 0, i = 0, misses = 0;
    while (m > 3) {
        uint32_t ip = idx[(i + m - 1) % m], ic = idx[i % m], in = idx[(i + 1) % m];
        const double *a = xy + 2 * ip, *b = xy + 2 * ic, *c = xy + 2 * in;
        int ear = cross2(a, b, c) > 0;
        for (uint32_t k = 0; ear && k < m; k++) {
            uint32_t v = idx[k];
            if (v == ip || v == ic || v == in) continue;
            const double *p = xy + 2 * v;
            if ((p[0] == a[0] && p[1] == a[1]) || (p[0] == c[0] && p[1] == c[1])) continue;
            if (in_triangle(p, a, b, c)) ear = 0;
        }
        if (ear) {
            tri[3 * t] = ip, tri[3 * t + 1] = ic, tri[3 * t + 2] = in;
            t++;
            for (uint32_t k = i % m; k + 1 < m; k++) idx[k] = idx[k + 1];
            m--;
            misses = 0;
            if (i >= m) i = 0;
            continue;
        }
        i = (i + 1) % m;
        if (++misses > m) {
            /* No ear: the outline crosses itself. The rest becomes a fan. */
            for (uint32_t k = 1; k + 1 < m; k++) {
                tri[3 * t] = idx[0], tri[3 * t + 1] = idx[k], tri[3 * t + 2] = idx[k + 1];
                t++;
            }
            return t;
        }
    }
    tri[3 * t] = idx[0], tri[3 * t + 1] = idx[1], tri[3 * t + 2] = idx[2];
    return t + 1;
}
