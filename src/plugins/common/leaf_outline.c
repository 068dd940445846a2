/* leaf_outline.c — the leaf mask's outline traced, simplified and triangulated (leaf_outline.h). */
#include "leaf_outline.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct edge {
    uint32_t from, to; /* texel-corner indices, y * (size + 1) + x, y counted up from the bottom */
    int used;
} edge;

typedef struct point {
    double x, y;
} point;

static int inside_at(const uint8_t *m, uint32_t n, int64_t c, int64_t y) /* y up from the bottom */
{
    return c >= 0 && y >= 0 && c < n && y < n && m[(size_t)(n - 1 - y) * n + (size_t)c];
}

/* The boundary edges of the inside texels, each with the inside on its left, and for every
 * corner the (at most two) edges leaving it. */
static int boundary_edges(const uint8_t *m, uint32_t n, edge **edges, size_t *count, int32_t **leaving)
{
    size_t cap = 0, k = 0, corners = (size_t)(n + 1) * (n + 1);
    for (uint32_t y = 0; y < n; y++)
        for (uint32_t c = 0; c < n; c++)
            if (inside_at(m, n, c, y))
                cap += !inside_at(m, n, c, (int64_t)y - 1) + !inside_at(m, n, c + 1, y) +
                       !inside_at(m, n, c, (int64_t)y + 1) + !inside_at(m, n, (int64_t)c - 1, y);
    edge *e = malloc((cap ? cap : 1) * sizeof *e);          /* owned by the caller */
    int32_t *out = malloc(corners * 2 * sizeof *out);       /* owned by the caller */
    if (!e || !out) {
        free(e), free(out);
        return -1;
    }
    for (size_t i = 0; i < corners * 2; i++) out[i] = -1;
    uint32_t w = n + 1;
    for (uint32_t y = 0; y < n; y++)
        for (uint32_t c = 0; c < n; c++) {
            if (!inside_at(m, n, c, y)) continue;
            uint32_t ll = y * w + c, lr = ll + 1, ul = ll + w, ur = ul + 1;
            uint32_t sides[4][2] = {{ll, lr}, {lr, ur}, {ur, ul}, {ul, ll}};
            int open[4] = {!inside_at(m, n, c, (int64_t)y - 1), !inside_at(m, n, c + 1, y),
                           !inside_at(m, n, c, (int64_t)y + 1), !inside_at(m, n, (int64_t)c - 1, y)};
            for (int s = 0; s < 4; s++) {
                if (!open[s]) continue;
                e[k] = (edge){sides[s][0], sides[s][1], 0};
                out[2 * (size_t)sides[s][0] + (out[2 * (size_t)sides[s][0]] >= 0)] = (int32_t)k;
                k++;
            }
        }
    *edges = e, *count = k, *leaving = out;
    return 0;
}

static double cross(point o, point a, point b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

static double signed_area(const point *p, size_t n)
{
    double a = 0;
    for (size_t i = 0; i < n; i++) a += p[i].x * p[(i + 1) % n].y - p[(i + 1) % n].x * p[i].y;
    return 0.5 * a;
}

/* Follows unused edges from edge `start` round its loop into p (corner points, collinear ones
 * left out); at a corner with two ways on it turns left, which keeps texels that meet only at a
 * corner apart. Returns the points written. */
static size_t follow(edge *e, const int32_t *leaving, uint32_t n, size_t start, point *p)
{
    uint32_t w = n + 1;
    size_t count = 0, at = start;
    for (;;) {
        e[at].used = 1;
        point q = {(double)(e[at].to % w), (double)(e[at].to / w)};
        const int32_t *ways = leaving + 2 * (size_t)e[at].to;
        int32_t next = -1;
        if (ways[1] >= 0) { /* a saddle: the way that turns left of the incoming direction */
            point a = {(double)(e[at].from % w), (double)(e[at].from / w)};
            for (int k = 0; k < 2; k++) {
                point b = {(double)(e[ways[k]].to % w), (double)(e[ways[k]].to / w)};
                if (!e[ways[k]].used && cross(a, q, b) > 0) next = ways[k];
            }
            if (next < 0) next = !e[ways[0]].used ? ways[0] : ways[1];
        } else {
            next = ways[0];
        }
        point b = {(double)(e[next].to % w), (double)(e[next].to / w)};
        point a = {(double)(e[at].from % w), (double)(e[at].from / w)};
        if (cross(a, q, b) != 0) p[count++] = q; /* a corner of the boundary */
        if ((size_t)next == start || e[next].used) break;
        at = (size_t)next;
    }
    return count;
}

/* Douglas-Peucker over p[i..j] (indices modulo n): marks keep[] for the points to keep. */
static void simplify(const point *p, size_t n, size_t i, size_t j, double tol, uint8_t *keep)
{
    size_t span = (j + n - i) % n;
    if (span < 2) return;
    point a = p[i], b = p[j % n];
    double len = hypot(b.x - a.x, b.y - a.y), worst = -1;
    size_t at = i;
    for (size_t k = 1; k < span; k++) {
        point q = p[(i + k) % n];
        double d = len > 0 ? fabs(cross(a, b, q)) / len : hypot(q.x - a.x, q.y - a.y);
        if (d > worst) worst = d, at = (i + k) % n;
    }
    if (worst <= tol) return;
    keep[at] = 1;
    simplify(p, n, i, at, tol, keep);
    simplify(p, n, at, j, tol, keep);
}

static int point_in_triangle(point q, point a, point b, point c)
{
    return cross(a, b, q) >= 0 && cross(b, c, q) >= 0 && cross(c, a, q) >= 0;
}

/* Ear clipping of the counter-clockwise polygon p (n >= 3) into tri. Returns 0, or -1 when no
 * ear is found (the polygon crosses itself). */
static int triangulate(const point *p, uint32_t n, uint32_t (*tri)[3])
{
    uint32_t *ring = malloc(n * sizeof *ring); /* owned here */
    if (!ring) return -1;
    for (uint32_t i = 0; i < n; i++) ring[i] = i;
    uint32_t left = n, t = 0;
    int rc = 0;
    while (left > 3) {
        int clipped = 0;
        for (uint32_t k = 0; k < left && !clipped; k++) {
            uint32_t ia = ring[(k + left - 1) % left], ib = ring[k], ic = ring[(k + 1) % left];
            if (cross(p[ia], p[ib], p[ic]) <= 0) continue; /* reflex or flat */
            int ear = 1;
            for (uint32_t m = 0; m < left && ear; m++) {
                uint32_t iq = ring[m];
                if (iq != ia && iq != ib && iq != ic && point_in_triangle(p[iq], p[ia], p[ib], p[ic])) ear = 0;
            }
            if (!ear) continue;
            tri[t][0] = ia, tri[t][1] = ib, tri[t][2] = ic, t++;
            memmove(ring + k, ring + k + 1, (left - k - 1) * sizeof *ring);
            left--, clipped = 1;
        }
        if (!clipped) {
            rc = -1;
            break;
        }
    }
    if (!rc) tri[t][0] = ring[0], tri[t][1] = ring[1], tri[t][2] = ring[2];
    free(ring);
    return rc;
}

/* The outer loop of the boundary, as corner points, into *loop (owned by the caller). */
static int outer_loop(const uint8_t *m, uint32_t n, point **loop, size_t *count)
{
    edge *e;
    int32_t *leaving;
    size_t ne;
    if (boundary_edges(m, n, &e, &ne, &leaving)) return -1;
    point *p = malloc((ne ? ne : 1) * sizeof *p), *best = malloc((ne ? ne : 1) * sizeof *best); /* owned here */
    size_t nb = 0;
    double best_area = 0;
    int rc = p && best ? 0 : -1;
    for (size_t s = 0; !rc && s < ne; s++) {
        if (e[s].used) continue;
        size_t k = follow(e, leaving, n, s, p);
        double a = k >= 3 ? signed_area(p, k) : 0;
        if (a > best_area) best_area = a, nb = k, memcpy(best, p, k * sizeof *p);
    }
    free(e), free(leaving), free(p);
    if (rc) {
        free(best);
        return -1;
    }
    *loop = best, *count = nb;
    return 0;
}

int leaf_outline_trace(const uint8_t *inside, uint32_t size, double tolerance, leaf_outline *out)
{
    memset(out, 0, sizeof *out);
    point *loop;
    size_t n;
    if (outer_loop(inside, size, &loop, &n)) return -1;
    if (n < 3) {
        free(loop);
        return 1;
    }
    uint8_t *keep = malloc(n);              /* owned here */
    point *poly = malloc(n * sizeof *poly); /* owned here */
    int rc = keep && poly ? 2 : -1;         /* 2: no polygon found yet */
    /* the points farthest apart along x split the closed loop into two chains */
    size_t lo = 0, hi = 0;
    for (size_t i = 1; i < n; i++) {
        if (loop[i].x < loop[lo].x) lo = i;
        if (loop[i].x > loop[hi].x) hi = i;
    }
    double tol = fmax(tolerance, 0.0);
    for (int attempt = 0; rc == 2 && attempt < 40; attempt++) {
        memset(keep, 0, n);
        keep[lo] = keep[hi] = 1;
        simplify(loop, n, lo, hi, tol, keep);
        simplify(loop, n, hi, lo, tol, keep);
        uint32_t m = 0;
        for (size_t i = 0; i < n; i++)
            if (keep[i]) poly[m++] = loop[i];
        if (m < 3) { /* simplified to a line: a finer outline */
            tol *= 0.5;
            continue;
        }
        if (m > LEAF_OUTLINE_MAX_VERTICES) { /* too fine: a coarser outline */
            tol = tol > 0 ? tol * 1.5 : 0.5;
            continue;
        }
        out->xy = malloc(m * sizeof *out->xy);         /* owned by out */
        out->tri = malloc((m - 2) * sizeof *out->tri); /* owned by out */
        if (!out->xy || !out->tri) {
            rc = -1;
            break;
        }
        if (triangulate(poly, m, out->tri)) { /* simplified across itself: a finer outline */
            free(out->xy), free(out->tri);
            out->xy = NULL, out->tri = NULL;
            tol *= 0.5;
            continue;
        }
        for (uint32_t i = 0; i < m; i++) out->xy[i][0] = poly[i].x / size, out->xy[i][1] = poly[i].y / size;
        out->n = m, out->nt = m - 2;
        rc = 0;
    }
    free(keep), free(poly), free(loop);
    if (rc) leaf_outline_free(out);
    return rc == 2 ? 1 : rc;
}

double leaf_outline_area(const leaf_outline *o)
{
    double a = 0;
    for (uint32_t t = 0; t < o->nt; t++) {
        const double *p = o->xy[o->tri[t][0]], *q = o->xy[o->tri[t][1]], *r = o->xy[o->tri[t][2]];
        a += 0.5 * ((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
    }
    return a;
}

void leaf_outline_free(leaf_outline *o)
{
    if (!o) return;
    free(o->xy), free(o->tri);
    memset(o, 0, sizeof *o);
}
