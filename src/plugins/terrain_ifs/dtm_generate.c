/* dtm_generate.c — midpoint displacement for a coarse seeded DTM. */
#include "dtm_generate.h"

#include <math.h>
#include <stdlib.h>

/* A displacement in [-1, 1). */
static double signed_unit(uint64_t (*rng_u64)(sylva_rng *), sylva_rng *rng)
{
    return (double)(rng_u64(rng) >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

int ifs_dtm_generate(const ifs_dtm_generator *g, uint64_t (*rng_u64)(sylva_rng *), sylva_rng *rng,
                     ifs_dtm **out, plugin_err *err)
{
    *out = NULL;
    if (g->nx > IFS_GENERATED_MAX_SIDE || g->ny > IFS_GENERATED_MAX_SIDE)
        return plugin_fail(err, SYLVA_ERR_LIMIT,
                        "a generated DTM of %u x %u nodes is larger than %u along a side", g->nx,
                        g->ny, IFS_GENERATED_MAX_SIDE);
    if (!(g->smoothness > 0 && g->smoothness <= 1) || !(g->relief >= 0 && isfinite(g->relief)))
        return plugin_fail(err, SYLVA_ERR_PARAM,
                        "generated DTM: smoothness %g must be in (0, 1] and relief %g m at least 0",
                        g->smoothness, g->relief);
    int rc = ifs_dtm_new(g->nx, g->ny, g->dx, g->dy, out, err);
    if (rc) return rc;
    uint32_t side = 2, big = g->nx > g->ny ? g->nx : g->ny;
    while (side + 1 < big) side *= 2;
    uint32_t n = side + 1;
    double *h = malloc((size_t)n * n * sizeof *h); /* owned here: the full 2^k + 1 square */
    if (!h) {
        ifs_dtm_free(*out), *out = NULL;
        return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory generating a %u x %u DTM", n, n);
    }
#define H(i, j) h[(size_t)(j) * n + (i)]
    H(0, 0) = signed_unit(rng_u64, rng), H(side, 0) = signed_unit(rng_u64, rng);
    H(0, side) = signed_unit(rng_u64, rng), H(side, side) = signed_unit(rng_u64, rng);
    double amp = 1.0, shrink = pow(2.0, -g->smoothness);
    for (uint32_t s = side; s > 1; s /= 2) {
        uint32_t half = s / 2;
        /* diamond: centre of each square from its four corners */
        for (uint32_t j = half; j < n; j += s)
            for (uint32_t i = half; i < n; i += s)
                H(i, j) = 0.25 * (H(i - half, j - half) + H(i + half, j - half) +
                                  H(i - half, j + half) + H(i + half, j + half)) +
                          amp * signed_unit(rng_u64, rng);
        /* square: edge midpoints from the (up to four) neighbours along the axes */
        for (uint32_t j = 0; j < n; j += half)
            for (uint32_t i = (j / half) % 2 ? 0 : half; i < n; i += s) {
                double sum = 0;
                int count = 0;
                if (i >= half) sum += H(i - half, j), count++;
                if (i + half < n) sum += H(i + half, j), count++;
                if (j >= half) sum += H(i, j - half), count++;
                if (j + half < n) sum += H(i, j + half), count++;
                H(i, j) = sum / count + amp * signed_unit(rng_u64, rng);
            }
        amp *= shrink;
    }
    ifs_dtm *d = *out;
    double lo = INFINITY, hi = -INFINITY;
    for (uint32_t j = 0; j < d->ny; j++)
        for (uint32_t i = 0; i < d->nx; i++) {
            double z = H(i, j);
            d->z[(size_t)j * d->nx + i] = z;
            if (z < lo) lo = z;
            if (z > hi) hi = z;
        }
#undef H
    free(h);
    double scale = hi > lo ? g->relief / (hi - lo) : 0.0;
    for (size_t k = 0; k < (size_t)d->nx * d->ny; k++) d->z[k] = (d->z[k] - lo) * scale;
    return SYLVA_OK;
}
