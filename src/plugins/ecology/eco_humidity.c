/* eco_humidity.c — humidity by rain runoff, 004 Algorithm 3 with (4.5)–(4.8): rain on every
 * patch, more on water patches, runoff from the highest patch to the lowest, then a low-pass
 * of N_mblur 5-point averages, normalised to [0, 1] over the land with water patches at 1. */
#include <stdlib.h>

#include "eco_terrain.h"

typedef struct patch_order {
    double z;
    uint32_t p;
} patch_order;

/* Highest first; equal heights in index order, so the visit order is fixed. */
static int higher_first(const void *a, const void *b)
{
    const patch_order *x = a, *y = b;
    if (x->z != y->z) return x->z > y->z ? -1 : 1;
    return x->p < y->p ? -1 : x->p > y->p;
}

int eco_humidity(eco_terrain *t, const eco_factor_params *fp)
{
    uint32_t ni = t->ni, nk = t->nk;
    size_t n = (size_t)ni * nk;
    double *m = malloc(n * sizeof *m), *next = malloc(n * sizeof *next);
    patch_order *order = malloc(n * sizeof *order);
    if (!m || !next || !order) {
        free(m), free(next), free(order);
        return -1;
    }
    /* (4.5): every patch gets m_climate, water patches m_w more. */
    for (size_t p = 0; p < n; p++) {
        m[p] = fp->rain + (t->water[p] ? fp->water_humidity : 0.0);
        order[p] = (patch_order){t->cz[p], (uint32_t)p};
    }
    qsort(order, n, sizeof *order, higher_first);
    /* Runoff: Algorithm 3 scales the share by the patch's own humidity m (4.6 omits it; the
     * algorithm is followed): Δ = m s k_m / n to each of the n lower 4-neighbours (4.7), n Δ
     * leaves the patch (4.8). */
    for (size_t j = 0; j < n; j++) {
        uint32_t p = order[j].p, i = p % ni, k = p / ni;
        uint32_t lower[4], nl = 0;
        if (i > 0 && t->cz[p - 1] < t->cz[p]) lower[nl++] = p - 1;
        if (i + 1 < ni && t->cz[p + 1] < t->cz[p]) lower[nl++] = p + 1;
        if (k > 0 && t->cz[p - ni] < t->cz[p]) lower[nl++] = p - ni;
        if (k + 1 < nk && t->cz[p + ni] < t->cz[p]) lower[nl++] = p + ni;
        if (!nl) continue;
        double share = m[p] * t->factor[ECO_SLOPE][p] * fp->runoff / nl;
        for (uint32_t q = 0; q < nl; q++) m[lower[q]] += share;
        m[p] -= nl * share;
    }
    /* N_mblur passes of the average of a patch and its four distinct neighbours (the printed
     * stencil lists (i, k+1) twice); at the border, of those that exist. */
    for (uint32_t pass = 0; pass < fp->humidity_blur; pass++) {
        for (uint32_t k = 0; k < nk; k++)
            for (uint32_t i = 0; i < ni; i++) {
                size_t p = i + (size_t)k * ni;
                double s = m[p];
                int c = 1;
                if (i > 0) s += m[p - 1], c++;
                if (i + 1 < ni) s += m[p + 1], c++;
                if (k > 0) s += m[p - ni], c++;
                if (k + 1 < nk) s += m[p + ni], c++;
                next[p] = s / c;
            }
        double *tmp = m;
        m = next, next = tmp;
    }
    /* To [0, 1] by the land's minimum and maximum, water patches 1: with m_w of ten times the
     * rain, the water's own values would otherwise squeeze every land value toward 0. */
    double lo = 0, hi = 0;
    int land = 0;
    for (size_t p = 0; p < n; p++) {
        if (t->water[p]) continue;
        if (!land || m[p] < lo) lo = m[p];
        if (!land || m[p] > hi) hi = m[p];
        land = 1;
    }
    if (!land) eco_normalise(m, n);
    for (size_t p = 0; p < n; p++) {
        double v = !land ? m[p] : t->water[p] ? 1.0 : hi > lo ? (m[p] - lo) / (hi - lo) : 0.5;
        t->factor[ECO_HUMIDITY][p] = (float)v;
    }
    free(m), free(next), free(order);
    return 0;
}
