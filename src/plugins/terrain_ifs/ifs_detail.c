/* ifs_detail.c — the DTM's roughness and the alpha that continues it (ifs_detail.h). */
#include "ifs_detail.h"

#include <math.h>
#include <stddef.h>

#include "ifs_eval.h"

/* Departures this small against the heights are the rounding of a plane's. */
#define IFS_PLANE_TOLERANCE 1e-9

/* Sums of squared departures from the surface through every s-th node, over the whole coarse
 * cells: at the middles of each cell's south and west sides and its centre (half), and at every
 * place between its corners (all). */
static void departures(const ifs_dtm *d, uint32_t s, double *half, uint64_t *n_half, double *all, uint64_t *n_all)
{
    *half = *all = 0, *n_half = *n_all = 0;
    for (uint32_t j0 = 0; j0 + s < d->ny; j0 += s)
        for (uint32_t i0 = 0; i0 + s < d->nx; i0 += s) {
            const double *z = d->z + (size_t)j0 * d->nx + i0;
            double za = z[0], zb = z[s], zc = z[(size_t)s * d->nx], zd = z[(size_t)s * d->nx + s];
            for (uint32_t q = 0; q < s; q++)
                for (uint32_t p = 0; p < s; p++) {
                    if (!p && !q) continue;
                    double u = (double)p / s, v = (double)q / s;
                    double flat = (1 - v) * ((1 - u) * za + u * zb) + v * ((1 - u) * zc + u * zd);
                    double e = z[(size_t)q * d->nx + p] - flat, e2 = e * e;
                    *all += e2, ++*n_all;
                    if ((2 * p) % s == 0 && (2 * q) % s == 0) *half += e2, ++*n_half;
                }
        }
}

int ifs_roughness_measure(const ifs_dtm *d, ifs_roughness *r)
{
    *r = (ifs_roughness){0};
    if (d->nx < 5 || d->ny < 5) return -1;
    double h2, a2, h4, a4;
    uint64_t nh2, na2, nh4, na4;
    departures(d, 2, &h2, &nh2, &a2, &na2);
    departures(d, 4, &h4, &nh4, &a4, &na4);
    r->half2 = sqrt(h2 / (double)nh2), r->half4 = sqrt(h4 / (double)nh4), r->all4 = sqrt(a4 / (double)na4);
    double zmin, zmax;
    ifs_dtm_range(d, &zmin, &zmax);
    if (!(r->half2 > IFS_PLANE_TOLERANCE * (fabs(zmin) + fabs(zmax) + 1))) { /* a plane (to rounding) */
        r->half2 = r->half4 = r->all4 = 0;
        return 0;
    }
    r->hurst = r->half4 > 0 ? log2(r->half4 / r->half2) : -INFINITY;
    double h = fmin(fmax(r->hurst, 0.0), 2.0);
    double between = r->half4 > 0 ? r->all4 / r->half4 : 1.0;
    r->target = r->half2 / exp2(2 * h) * between; /* two octaves down: from 2 cells to half a cell */
    return 0;
}

/* Element k of the van der Corput sequence in base b (the Halton sequence's coordinates). */
static double radical_inverse(uint32_t k, uint32_t b)
{
    double f = 1.0, x = 0.0;
    for (; k; k /= b) f /= b, x += f * (k % b);
    return x;
}

void ifs_detail_measure(const ifs_maps *m, uint32_t depth, double *rms, double *max)
{
    if (!depth) depth = ifs_eval_auto_depth(m, (m->nx - 1) * IFS_DETAIL_REFINE + 1, (m->ny - 1) * IFS_DETAIL_REFINE + 1);
    double sum = 0, top = 0;
    for (uint32_t k = 1; k <= IFS_DETAIL_SAMPLES; k++) {
        double sx = radical_inverse(k, 2) * (m->nx - 1), sy = radical_inverse(k, 3) * (m->ny - 1);
        double e = ifs_eval_at(m, sx, sy, depth) - ifs_bilinear_at(m, sx, sy);
        sum += e * e, top = fmax(top, fabs(e));
    }

    *rms = sqrt(sum / IFS_DETAIL_SAMPLES), *max = top;
}

int ifs_alpha_for_detail(const ifs_dtm *d, ifs_mode mode, uint32_t depth, double target, double *alpha,
                         plugin_err *err)
{
    *alpha = 0;
    if (!(target > 0)) return 0;
    double a = 0.01;
    for (int step = 0; step < 8; step++) {
        ifs_maps *m = NULL;
        ifs_maps_params p = {.mode = mode, .alpha = a};
        int rc = ifs_maps_build(d, &p, &m, err);
        if (rc) return rc;
        double rms, max;
        ifs_detail_measure(m, depth, &rms, &max);
        ifs_maps_free(m);
        if (!(rms > 0)) return 0; /* the DTM has no departure to copy */
        double next = fmin(a * target / rms, IFS_ALPHA_AUTO_MAX);
        int settled = fabs(next - a) <= 1e-4 * a;
        a = next;
        if (settled || a == IFS_ALPHA_AUTO_MAX) break;
    }
    *alpha = a;
    return 0;
}
