/* sightline_exact.h — an exact line of sight over a heightfield given at nodes, independent of
 * sylva's tracer: the surface sylva draws over the nodes (two triangles per cell split along the
 * diagonal from its south-west to its north-east node, docs/sites.md), a sightline sagging below
 * the straight segment by CURVE s (S - s) followed by chords of at most CHORD_M metres, each chord
 * tested in double precision against every triangle of the cells it passes over: no BVH, no
 * single precision, no tolerance but the chord's. Header-only, for the ZTV check tools
 * (ztv_sightline_oracle.c, ztv_canopy_compare.c). */
#ifndef SYLVA_TEST_SIGHTLINE_EXACT_H
#define SYLVA_TEST_SIGHTLINE_EXACT_H

#include <math.h>
#include <stdint.h>
#include <string.h>

#define CHORD_M 100.0 /* longest chord of a curved sightline, metres */

typedef struct dtm {
    int nx, ny;       /* nodes; node (i, j): i east, j north, height z[(ny - 1 - j) nx + i] */
    double dx, dy;
    const float *z;
} dtm;

static inline double node_z(const dtm *d, int i, int j)
{
    return d->z[(size_t)(d->ny - 1 - j) * d->nx + i];
}

/* 1 when the segment o + u e, u in (0, 1), crosses the triangle (a, b, c) (Moller-Trumbore). */
static inline int crosses(const double o[3], const double e[3], const double a[3], const double b[3], const double c[3])
{
    double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double p[3] = {e[1] * e2[2] - e[2] * e2[1], e[2] * e2[0] - e[0] * e2[2], e[0] * e2[1] - e[1] * e2[0]};
    double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (det == 0.0) return 0;
    double s[3] = {o[0] - a[0], o[1] - a[1], o[2] - a[2]};
    double u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
    if (u < 0 || u > 1) return 0;
    double q[3] = {s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]};
    double v = (e[0] * q[0] + e[1] * q[1] + e[2] * q[2]) / det;
    if (v < 0 || u + v > 1) return 0;
    double t = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
    return t > 1e-9 && t < 1 - 1e-9;
}

/* 1 when the segment from o along e crosses the ground of cell (i, j) (south-west node). */
static inline int crosses_cell(const dtm *d, int i, int j, const double o[3], const double e[3])
{
    if (i < 0 || j < 0 || i >= d->nx - 1 || j >= d->ny - 1) return 0;
    double sw[3] = {i * d->dx, j * d->dy, node_z(d, i, j)}, se[3] = {(i + 1) * d->dx, j * d->dy, node_z(d, i + 1, j)};
    double ne[3] = {(i + 1) * d->dx, (j + 1) * d->dy, node_z(d, i + 1, j + 1)};
    double nw[3] = {i * d->dx, (j + 1) * d->dy, node_z(d, i, j + 1)};
    return crosses(o, e, sw, se, ne) || crosses(o, e, sw, ne, nw);
}

/* 1 when the segment from a to b crosses the ground: every cell within one of a point of its
 * trace taken each quarter cell is tested. */
static inline int segment_blocked(const dtm *d, const double a[3], const double b[3])
{
    double e[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    int n = (int)(hypot(e[0], e[1]) / (0.25 * fmin(d->dx, d->dy))) + 2, last_i = INT32_MIN, last_j = INT32_MIN;
    for (int k = 0; k <= n; k++) {
        int i = (int)floor((a[0] + e[0] * k / n) / d->dx), j = (int)floor((a[1] + e[1] * k / n) / d->dy);
        if (i == last_i && j == last_j) continue;
        last_i = i, last_j = j;
        for (int dj = -1; dj <= 1; dj++)
            for (int di = -1; di <= 1; di++)
                if (crosses_cell(d, i + di, j + dj, a, e)) return 1;
    }
    return 0;
}

/* 1 when the sightline from eye o to target t is clear (coordinates from node (0, 0)). */
static inline int sightline_clear(const dtm *d, const double o[3], const double t[3], double curve)
{
    double span = hypot(t[0] - o[0], t[1] - o[1]);
    int chords = curve > 0 ? (int)ceil(span / CHORD_M) : 1;
    if (chords < 1) chords = 1;
    double a[3] = {o[0], o[1], o[2]};
    for (int k = 1; k <= chords; k++) {
        double u = (double)k / chords;
        double b[3] = {o[0] + u * (t[0] - o[0]), o[1] + u * (t[1] - o[1]),
                       o[2] + u * (t[2] - o[2]) - curve * span * span * u * (1 - u)};
        if (segment_blocked(d, a, b)) return 0;
        memcpy(a, b, sizeof a);
    }
    return 1;
}

#endif
