/* eco_edge.c — the growth area's edge as a band where seedlings take root less and less often
 * (docs/models/ecology.md, "Forest edges"). Inside the area (rectangle or mask) every seedling
 * may take root, as in 004; outside it, one that lands at distance d from the area takes root
 * with chance
 *
 *     e(d) = 1 - S(d / fade + 0.75 (2 n - 1)),    S(t) = smoothstep on [0, 1],
 *
 * n in [0, 1] a smooth value noise of the map (two octaves, lattices fade and 0.4 fade metres
 * apart, stretched to fill [0, 1]), so the edge wanders by up to three quarters of the band in
 * and out instead of following the rectangle. Beyond 1.75 fade nothing takes root. d is a chamfer distance (3-4 weights scaled to
 * the patch size) from the nearest patch of the area, in metres between patch centres. */
#include <math.h>
#include <stdlib.h>

#include "eco_sim.h"

static uint64_t mix64(uint64_t z)
{
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/* The lattice value at (ix, iy), in [0, 1). */
static double lattice(uint64_t seed, int64_t ix, int64_t iy)
{
    return (double)(mix64(seed ^ mix64((uint64_t)ix * 0x9e3779b97f4a7c15ull ^ (uint64_t)iy)) >> 11) *
           (1.0 / 9007199254740992.0);
}

static double smooth(double t) { return t <= 0 ? 0 : t >= 1 ? 1 : t * t * (3 - 2 * t); }

/* Value noise with lattice spacing `cell` metres: the lattice values blended by smoothstep. */
static double value_noise(uint64_t seed, double x, double y, double cell)
{
    double fx = x / cell, fy = y / cell;
    int64_t ix = (int64_t)floor(fx), iy = (int64_t)floor(fy);
    double u = smooth(fx - ix), v = smooth(fy - iy);
    double a = lattice(seed, ix, iy), b = lattice(seed, ix + 1, iy);
    double c = lattice(seed, ix, iy + 1), d = lattice(seed, ix + 1, iy + 1);
    return (a + (b - a) * u) * (1 - v) + (c + (d - c) * u) * v;
}

double eco_edge_chance(double d, double fade, double noise)
{
    if (d <= 0) return 1;
    if (!(fade > 0)) return 0;
    return 1 - smooth(d / fade + 0.75 * (2 * noise - 1));
}

float *eco_edge_establishment(const eco_terrain *t, const uint8_t *inside, double fade, uint64_t seed)
{
    size_t n = (size_t)t->ni * t->nk;
    float *e = malloc(n * sizeof *e);
    double *d = malloc(n * sizeof *d);
    if (!e || !d) {
        free(e), free(d);
        return NULL;
    }
    /* chamfer distance transform: a forward and a backward pass over the patches */
    const double wx = t->kx, wy = t->ky, wd = hypot(t->kx, t->ky);
    for (size_t p = 0; p < n; p++) d[p] = inside[p] ? 0 : INFINITY;
    for (uint32_t k = 0; k < t->nk; k++)
        for (uint32_t i = 0; i < t->ni; i++) {
            double *q = &d[(size_t)k * t->ni + i];
            if (i > 0) *q = fmin(*q, q[-1] + wx);
            if (k > 0) {
                *q = fmin(*q, q[-(ptrdiff_t)t->ni] + wy);
                if (i > 0) *q = fmin(*q, q[-(ptrdiff_t)t->ni - 1] + wd);
                if (i + 1 < t->ni) *q = fmin(*q, q[-(ptrdiff_t)t->ni + 1] + wd);
            }
        }
    for (uint32_t k = t->nk; k-- > 0;)
        for (uint32_t i = t->ni; i-- > 0;) {
            double *q = &d[(size_t)k * t->ni + i];
            if (i + 1 < t->ni) *q = fmin(*q, q[1] + wx);
            if (k + 1 < t->nk) {
                *q = fmin(*q, q[t->ni] + wy);
                if (i + 1 < t->ni) *q = fmin(*q, q[t->ni + 1] + wd);
                if (i > 0) *q = fmin(*q, q[t->ni - 1] + wd);
            }
        }
    for (uint32_t k = 0; k < t->nk; k++)
        for (uint32_t i = 0; i < t->ni; i++) {
            size_t p = (size_t)k * t->ni + i;
            double x = t->x0 + (i + 0.5) * t->kx, y = t->y0 + (k + 0.5) * t->ky;
            double noise = 0.5;
            if (d[p] > 0 && d[p] < 1.75 * fade) {
                /* two octaves average toward 0.5: stretch them back to about [0, 1] */
                double v = (2.0 * value_noise(seed, x, y, fade) + value_noise(seed + 1, x, y, 0.4 * fade)) / 3.0;
                v = 0.5 + 2.0 * (v - 0.5);
                noise = v < 0 ? 0 : v > 1 ? 1 : v;
            }
            e[p] = (float)eco_edge_chance(d[p], fade, noise);
        }
    free(d);
    return e;
}
