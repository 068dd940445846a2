/* ztv_sweep.c — bare-earth visibility from one target by rays walked over the ground's triangles. */
#include "ztv/ztv_sweep.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ztv/ztv_sight.h"

/* The target in the window's node coordinates. */
typedef struct target {
    double u, v;       /* nodes east and north of the window's south-west node */
    double z;          /* its height */
    double height;     /* above the ground under it */
} target;

/* The crossings of a walk along a line of the window with the grid's three families of lines:
 * u = k (kind 0), v = k (kind 1) and the diagonals u - v = k (kind 2). */
typedef struct walker {
    double u0, v0, a, b;    /* start, and nodes per metre along u and v */
    double per[3], from[3]; /* metres per line of each family; where it starts among them */
    double t[3];            /* distance of each family's next line */
    long next[3];
    int step[3];
} walker;

static void walker_start(walker *w, double u0, double v0, double a, double b)
{
    double rate[3] = {a, b, a - b};
    *w = (walker){.u0 = u0, .v0 = v0, .a = a, .b = b, .from = {u0, v0, u0 - v0}};
    for (int k = 0; k < 3; k++) {
        double x = w->from[k];
        w->step[k] = rate[k] > 0 ? 1 : rate[k] < 0 ? -1 : 0;
        w->next[k] = rate[k] > 0 ? (long)floor(x) + 1 : (long)ceil(x) - 1;
        w->per[k] = w->step[k] ? 1.0 / rate[k] : 0.0;
        w->t[k] = w->step[k] ? (w->next[k] - x) * w->per[k] : INFINITY; /* INFINITY: it runs along them */
    }
}

/* The next crossing: its distance from the start, its family and its line. */
static inline double walker_next(walker *w, int *kind, long *line)
{
    int k = w->t[0] <= w->t[1] && w->t[0] <= w->t[2] ? 0 : w->t[1] <= w->t[2] ? 1 : 2;
    double t = w->t[k];
    *kind = k, *line = w->next[k];
    w->next[k] += w->step[k];
    w->t[k] = (w->next[k] - w->from[k]) * w->per[k];
    return t;
}

static double node_z(const ztv_sweep_ground *g, long a, long b)
{
    return g->z[(size_t)(g->j0 + b) * g->stride + g->i0 + (size_t)a];
}

/* (long)floor(x) for a finite x within a long's range, without a call into libm. */
static inline long floor_long(double x)
{
    long i = (long)x;
    return i - (x < (double)i);
}

static inline double most(double a, double b)
{
    return a > b ? a : b;
}

static long clamp_cell(long k, uint32_t nodes)
{
    return k < 0 ? 0 : k > (long)nodes - 2 ? (long)nodes - 2 : k;
}

/* The ground at (u, v) on line `line` of family kind, exact on the triangles' edges; NAN off the
 * window. */
static double crossing_height(const ztv_sweep_ground *g, int kind, long line, double u, double v)
{
    if (kind == 0) {
        if (line < 0 || line >= (long)g->nx) return NAN;
        long b = clamp_cell((long)v, g->ny); /* v >= 0 but for rounding: truncation is floor */
        double z0 = node_z(g, line, b);
        return z0 + (v - b) * (node_z(g, line, b + 1) - z0);
    }
    if (kind == 1) {
        if (line < 0 || line >= (long)g->ny) return NAN;
        long a = clamp_cell((long)u, g->nx);
        double z0 = node_z(g, a, line);
        return z0 + (u - a) * (node_z(g, a + 1, line) - z0);
    }
    long a = clamp_cell((long)u, g->nx), b = a - line;
    if (b < 0 || b > (long)g->ny - 2) return NAN;
    double z0 = node_z(g, a, b);
    return z0 + (u - a) * (node_z(g, a + 1, b + 1) - z0);
}

/* The ground anywhere in the window (the triangle holding (u, v)). */
static double ground_at(const ztv_sweep_ground *g, double u, double v)
{
    long a = clamp_cell((long)floor(u), g->nx), b = clamp_cell((long)floor(v), g->ny);
    double fx = u - a, fy = v - b, z00 = node_z(g, a, b), z11 = node_z(g, a + 1, b + 1);
    if (fx >= fy) {
        double z10 = node_z(g, a + 1, b);
        return z00 + fx * (z10 - z00) + fy * (z11 - z10);
    }
    double z01 = node_z(g, a, b + 1);
    return z00 + fy * (z01 - z00) + fx * (z11 - z01);
}

/* The steepness of cell (a, b), or of the window's cell nearest it. */
static inline double steep_at(const ztv_sweep_ground *g, long a, long b)
{
    unsigned long cx = g->nx - 1, cy = g->ny - 1;
    if ((unsigned long)a >= cx || (unsigned long)b >= cy) a = clamp_cell(a, g->nx), b = clamp_cell(b, g->ny);
    return g->steep[(size_t)b * cx + (size_t)a];
}

void ztv_sweep_steepness(const ztv_sweep_ground *g, float *steep)
{
    uint32_t cx = g->nx - 1, cy = g->ny - 1;
    for (uint32_t b = 0; b < cy; b++)
        for (uint32_t a = 0; a < cx; a++) {
            double z00 = node_z(g, a, b), z10 = node_z(g, a + 1, b), z01 = node_z(g, a, b + 1);
            double z11 = node_z(g, a + 1, b + 1);
            double ax = z10 - z00, ay = z11 - z10, bx = z11 - z01, by = z01 - z00; /* metres: no overflow */
            double lower = sqrt(ax * ax + ay * ay), upper = sqrt(bx * bx + by * by);
            steep[(size_t)b * cx + a] = (float)(fmax(lower, upper) / g->cell);
        }
    /* each cell takes its neighbours' too: along the rows, then along the columns */
    for (uint32_t b = 0; b < cy; b++) {
        float *r = steep + (size_t)b * cx, prev = r[0];
        for (uint32_t a = 0; a < cx; a++) {
            float cur = r[a], next = a + 1 < cx ? r[a + 1] : cur;
            r[a] = fmaxf(fmaxf(prev, cur), next);
            prev = cur;
        }
    }
    for (uint32_t a = 0; a < cx; a++) {
        float prev = steep[a];
        for (uint32_t b = 0; b < cy; b++) {
            float *p = steep + (size_t)b * cx + a, cur = *p, next = b + 1 < cy ? p[cx] : cur;
            *p = fmaxf(fmaxf(prev, cur), next);
            prev = cur;
        }
    }
}

/* What a walked ray knows at crossing k: its distance; the horizons with the slack above and below
 * the ground, and the steepness passed, up to there; and at the crossing alone, the two terms
 * whose running greatest are the horizons, and the steepness of the cell the ray came through to
 * it (the segment from the crossing before). */
enum { AT_T, AT_ABOVE, AT_BELOW, AT_STEEP, AT_UP, AT_DOWN, AT_CELL, AT_N };

/* The greatest of AT_UP, AT_DOWN and AT_CELL over each run of ZTV_SWEEP_RUN crossings, so that
 * node_status can pass over a run in one step where none of its crossings can change the answer. */
#define ZTV_SWEEP_RUN 16u
enum { RUN_UP, RUN_DOWN, RUN_CELL, RUN_N };

int ztv_sweep_scratch_alloc(ztv_sweep_scratch *s, const ztv_sweep_ground *g)
{
    s->crossings = 2 * (g->nx + g->ny) + 16;
    s->nearest = malloc((size_t)g->nx * g->ny * sizeof *s->nearest);
    s->crossing = malloc((size_t)s->crossings * AT_N * sizeof *s->crossing);
    s->run = malloc(((size_t)s->crossings / ZTV_SWEEP_RUN + 1) * RUN_N * sizeof *s->run);
    return s->nearest && s->crossing && s->run ? 0 : -1;
}

void ztv_sweep_scratch_free(ztv_sweep_scratch *s)
{
    free(s->nearest), free(s->crossing), free(s->run);
    s->nearest = NULL, s->crossing = NULL, s->run = NULL;
}

/* The sightline from the eye at node (pa, pb), S metres from the target, walked exactly over
 * its first ZTV_SWEEP_NEAR cells (all of it when shorter): ZTV_HIDDEN when the ground stands
 * above it by more than the slack where the Embree sightline is traced, ZTV_SEEN when it stays
 * below by more than the slack all the way, else ZTV_DOUBT. */
static int near_walk(const ztv_sweep_ground *g, const target *tg, long pa, long pb, double eye, double S)
{
    double len = fmin(ZTV_SWEEP_NEAR * g->cell, S), c = g->c, least = eye - node_z(g, pa, pb), rprev = 0;
    double per_S = 1 / S, rise = (tg->z - eye) * per_S;
    walker w;
    walker_start(&w, (double)pa, (double)pb, (tg->u - pa) * per_S, (tg->v - pb) * per_S);
    for (;;) {
        int kind;
        long line;
        double r = walker_next(&w, &kind, &line);
        if (!(r <= S)) break;
        double h = crossing_height(g, kind, line, pa + w.a * r, pb + w.b * r);
        if (isnan(h)) continue;
        double m = eye + r * rise - c * r * (S - r) - h;
        if (m < -ZTV_SWEEP_SLACK && r >= 2 * ZTV_SIGHT_GAP && r <= S - 2 * ZTV_SIGHT_GAP) return ZTV_HIDDEN;
        /* between crossings the ground is straight and the sightline bows down by c dr^2 / 4 at most */
        double bowed = m - 0.25 * c * (r - rprev) * (r - rprev);
        least = bowed < least ? bowed : least;
        rprev = r;
        if (r >= len) break;
    }
    if (len >= S) least = fmin(least, tg->height - 0.25 * c * (S - rprev) * (S - rprev));
    return least > ZTV_SWEEP_SLACK ? ZTV_SEEN : ZTV_DOUBT;
}

/* The first of the n crossings recorded at distance t or beyond (the last when none): searched
 * back from the last, as t lies a few cells short of it. */
static uint32_t crossing_at(const double *rec, uint32_t n, double t)
{
    uint32_t k = n - 1;
    while (k > 0 && rec[AT_N * (k - 1) + AT_T] >= t) k--;
    return k;
}

/* The status of node (pa, pb), which the ray passes D metres away at its n-th crossing (t from
 * the target). */
static int node_status(const ztv_sweep_ground *g, const target *tg, const ztv_sweep_scratch *s, uint32_t n, long pa,
                       long pb, double eye, double D, double t)
{
    const double *rec = s->crossing;
    double eu = pa - tg->u, ev = pb - tg->v, S = sqrt(eu * eu + ev * ev) * g->cell, c = g->c;
    if (S < 1e-3) return ZTV_DOUBT;
    double rnear = ZTV_SWEEP_NEAR * g->cell;
    if (S <= rnear) return near_walk(g, tg, pa, pb, eye, S);
    double per_S = 1 / S, per_t = 1 / t;
    /* the ends' gaps cannot hide what the bound below blames on the ground next to them */
    double need = ZTV_SIGHT_GAP * (g->steepest + fabs(eye - tg->z) * per_S + c * S) + ZTV_SWEEP_SLACK;
    int may_hide = g->observer_height >= need && tg->height >= need;
    /* the rest: the ray as far as the share 1 - rnear / S of the way to the node */
    uint32_t last = crossing_at(rec, n, t * (1 - rnear * per_S));
    const double *at = rec + AT_N * last;
    double lam = S * S * per_t * per_t, skew = c * fabs(lam - 1) * t, drop = c * lam * t, G = at[AT_STEEP];
    double sight = (eye - tg->z) * per_t - drop, off = D * per_t; /* the sightline's slope; the offset's share */
    if (may_hide && at[AT_BELOW] - skew - G * off > sight) return ZTV_HIDDEN;
    int far_clear = at[AT_ABOVE] + skew + G * off < sight;
    int near = near_walk(g, tg, pa, pb, eye, S);
    if (near == ZTV_HIDDEN || (near == ZTV_SEEN && far_clear)) return near;
    if (near == ZTV_DOUBT && !may_hide) return ZTV_DOUBT;
    /* the bound again with each crossing's own steepness in place of the steepest passed: the
     * ground under the sightline at a crossing differs from the ray's by that of the cell the ray
     * came through, times the offset there; crossing by crossing, till the answer is known */
    int seen = near == ZTV_SEEN;
    for (uint32_t k = 0; k <= last && (seen || may_hide);) {
        const double *run = s->run + RUN_N * (k / ZTV_SWEEP_RUN);
        if (k % ZTV_SWEEP_RUN == 0 && k + ZTV_SWEEP_RUN - 1 <= last) { /* a whole run */
            if (may_hide && run[RUN_DOWN] - skew - run[RUN_CELL] * off > sight) return ZTV_HIDDEN;
            int may_cloud = seen && run[RUN_UP] + skew + run[RUN_CELL] * off >= sight;
            if (!may_cloud && !(may_hide && run[RUN_DOWN] - skew > sight)) {
                k += ZTV_SWEEP_RUN;
                continue;
            }
        }
        const double *r = rec + AT_N * k++;
        if (seen && r[AT_UP] + skew + r[AT_CELL] * off >= sight) seen = 0;
        if (may_hide && r[AT_DOWN] - skew - r[AT_CELL] * off > sight) return ZTV_HIDDEN;
    }
    return seen ? ZTV_SEEN : ZTV_DOUBT;
}

/* Walks the ray from the target to (ue, ve), trying each node not yet settled that it passes
 * nearer than any ray before it. The walker's state is held in locals and each family's
 * crossing has its own code, the edge's nodes read directly where the edge lies inside the
 * window (crossing_height's cases, without its clamps), since this loop is most of a map's time. */
static void walk_ray(const ztv_sweep_ground *g, const target *tg, double ue, double ve, uint8_t *status,
                     ztv_sweep_scratch *s)
{
    double du = ue - tg->u, dv = ve - tg->v, len = hypot(du, dv) * g->cell, c = g->c;
    if (len <= 0) return;
    walker w;
    walker_start(&w, tg->u, tg->v, du / len, dv / len);
    int own = fabs(du) >= fabs(dv) ? 0 : 1; /* the family of lines whose nodes it settles */
    double above = -INFINITY, below = -INFINITY, tprev = 0, tend = len * (1 + 1e-12), zt = tg->z;
    double steep = steep_at(g, (long)floor(tg->u), (long)floor(tg->v));
    double t0 = w.t[0], t1 = w.t[1], t2 = w.t[2];
    long n0 = w.next[0], n1 = w.next[1], n2 = w.next[2];
    const long cx = (long)g->nx - 1, cy = (long)g->ny - 1; /* the window's cells */
    const long back0 = w.step[0] < 0, back1 = w.step[1] < 0;
    const size_t stride = g->stride;
    const float *z = g->z + (size_t)g->j0 * stride + g->i0; /* node (0, 0) of the window */
    uint32_t n = 0;
    double cell = steep; /* the steepness of the cell the ray is in */
    while (n < s->crossings) {
        int kind;
        long line;
        double t, u, v, h, came = cell;
        if (t0 <= t1 && t0 <= t2) { /* u = line: the edge between (line, b) and (line, b + 1) */
            t = t0, line = n0, kind = 0;
            n0 += w.step[0], t0 = (n0 - w.from[0]) * w.per[0];
            if (!(t <= tend)) break;
            u = tg->u + w.a * t, v = tg->v + w.b * t;
            long b = (long)v, a = line - back0; /* a: the cell entered */
            if ((unsigned long)line <= (unsigned long)cx && (unsigned long)b < (unsigned long)cy) {
                const float *q = z + (size_t)b * stride + (size_t)line;
                h = q[0] + (v - b) * (q[stride] - q[0]);
            } else if (isnan(h = crossing_height(g, 0, line, u, v)))
                continue;
            cell = steep_at(g, a, b), steep = most(steep, cell);
        } else if (t1 <= t2) { /* v = line: the edge between (a, line) and (a + 1, line) */
            t = t1, line = n1, kind = 1;
            n1 += w.step[1], t1 = (n1 - w.from[1]) * w.per[1];
            if (!(t <= tend)) break;
            u = tg->u + w.a * t, v = tg->v + w.b * t;
            long a = (long)u, b = line - back1;
            if ((unsigned long)a < (unsigned long)cx && (unsigned long)line <= (unsigned long)cy) {
                const float *q = z + (size_t)line * stride + (size_t)a;
                h = q[0] + (u - a) * (q[1] - q[0]);
            } else if (isnan(h = crossing_height(g, 1, line, u, v)))
                continue;
            cell = steep_at(g, a, b), steep = most(steep, cell);
        } else { /* u - v = line: the diagonal of cell (a, a - line) */
            t = t2, line = n2, kind = 2;
            n2 += w.step[2], t2 = (n2 - w.from[2]) * w.per[2];
            if (!(t <= tend)) break;
            u = tg->u + w.a * t, v = tg->v + w.b * t;
            long a = (long)u, b = a - line;
            if ((unsigned long)a < (unsigned long)cx && (unsigned long)b < (unsigned long)cy) {
                const float *q = z + (size_t)b * stride + (size_t)a;
                h = q[0] + (u - a) * (q[stride + 1] - q[0]);
            } else if (isnan(h = crossing_height(g, 2, line, u, v)))
                continue;
        }
        double inv = 1.0 / t, base = (h - zt) * inv - c * t;
        /* between crossings (h - zT) / t - c t exceeds its value at the far one by c dt at most */
        double up = base + ZTV_SWEEP_SLACK * inv + c * (t - tprev), down = base - ZTV_SWEEP_SLACK * inv;
        above = most(above, up), below = most(below, down);
        tprev = t;
        double *r = s->crossing + AT_N * (size_t)n++;
        r[AT_T] = t, r[AT_ABOVE] = above, r[AT_BELOW] = below, r[AT_STEEP] = steep;
        r[AT_UP] = up, r[AT_DOWN] = down, r[AT_CELL] = came;
        double *run = s->run + RUN_N * ((n - 1) / ZTV_SWEEP_RUN);
        int first = (n - 1) % ZTV_SWEEP_RUN == 0; /* of its run */
        run[RUN_UP] = first ? up : most(run[RUN_UP], up);
        run[RUN_DOWN] = first ? down : most(run[RUN_DOWN], down);
        run[RUN_CELL] = first ? came : most(run[RUN_CELL], came);
        if (kind != own) continue;
        long pa = own ? floor_long(u + 0.5) : line, pb = own ? line : floor_long(v + 0.5);
        if (pa < 0 || pb < 0 || pa >= (long)g->nx || pb >= (long)g->ny) continue;
        size_t k = (size_t)(g->ny - 1 - pb) * g->nx + (size_t)pa;
        float D = (float)(fabs(own ? u - pa : v - pb) * g->cell);
        if (!(D < s->nearest[k])) continue; /* settled, no observer, or a nearer ray tried it */
        int st = node_status(g, tg, s, n, pa, pb, g->eye[k], D, t);
        status[k] = (uint8_t)st;
        s->nearest[k] = st == ZTV_DOUBT ? D : -1.0f;
    }
}

void ztv_sweep_target(const ztv_sweep_ground *g, const double t[3], uint8_t *status, ztv_sweep_scratch *s)
{
    size_t n = (size_t)g->nx * g->ny;
    memset(status, ZTV_DOUBT, n);
    for (size_t k = 0; k < n; k++) s->nearest[k] = isnan(g->eye[k]) ? -1.0f : INFINITY;
    target tg = {(t[0] - g->x0) / g->cell - g->i0, (t[1] - g->y0) / g->cell - g->j0, t[2], 0};
    double umax = g->nx - 1, vmax = g->ny - 1;
    if (!(tg.u >= 0 && tg.v >= 0 && tg.u <= umax && tg.v <= vmax)) return; /* all doubtful */
    tg.height = tg.z - ground_at(g, tg.u, tg.v);
    /* round the perimeter, so that each ray walks over the ground the one before it left in the
     * cache: along the south edge eastwards, up the east edge, back along the north edge, down the
     * west edge (each corner twice) */
    uint32_t m = ZTV_SWEEP_RAYS, east = g->nx * m - m, north = g->ny * m - m;
    for (uint32_t k = 0; k <= east; k++) walk_ray(g, &tg, (double)k / m, 0, status, s);
    for (uint32_t k = 0; k <= north; k++) walk_ray(g, &tg, umax, (double)k / m, status, s);
    for (uint32_t k = east + 1; k-- > 0;) walk_ray(g, &tg, (double)k / m, vmax, status, s);
    for (uint32_t k = north + 1; k-- > 0;) walk_ray(g, &tg, 0, (double)k / m, status, s);
}
