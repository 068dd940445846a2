/* dtm_fill.c — filling nodata nodes of a DTM from the known heights around each hole.
 *
 * Holes are filled ring by ring: the first ring is every nodata node touching a known node;
 * each node of a ring takes the weighted mean of the neighbours known before the ring started
 * (so the order inside a ring does not matter), then the ring counts as known and its nodata
 * neighbours form the next ring. Every node is visited a bounded number of times. */
#include <math.h>
#include <stdlib.h>

#include "dtm.h"
#include "sylva/plugin.h"

static const int ring_di[8] = {-1, 1, 0, 0, -1, 1, -1, 1};
static const int ring_dj[8] = {0, 0, -1, 1, -1, -1, 1, 1};
static const double ring_w[8] = {1, 1, 1, 1, M_SQRT1_2, M_SQRT1_2, M_SQRT1_2, M_SQRT1_2};

int ifs_dtm_fill_nodata(ifs_dtm *d, uint64_t *filled, plugin_err *err)
{
    size_t n = (size_t)d->nx * d->ny, missing = 0;
    *filled = 0;
    for (size_t k = 0; k < n; k++) missing += !isfinite(d->z[k]);
    if (!missing) return SYLVA_OK;
    if (missing == n)
        return plugin_fail(err, SYLVA_ERR_PARAM,
                        "every one of the DTM's %u x %u nodes is nodata; there is no height to "
                        "interpolate from (check the crop window and the file's nodata value)",
                        d->nx, d->ny);
    /* state: 0 known, 1 unknown, 2 queued for the next ring */
    unsigned char *state = malloc(n);             /* owned here */
    size_t *ring = malloc(missing * sizeof *ring); /* owned here: current ring */
    size_t *next = malloc(missing * sizeof *next); /* owned here: next ring */
    double *value = malloc(missing * sizeof *value);
    int rc = SYLVA_OK;
    if (!state || !ring || !next || !value) {
        rc = plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory filling %zu nodata nodes", missing);
        goto done;
    }
    size_t n_ring = 0;
    for (size_t k = 0; k < n; k++) state[k] = !isfinite(d->z[k]);
    for (uint32_t j = 0; j < d->ny; j++)
        for (uint32_t i = 0; i < d->nx; i++) {
            size_t k = (size_t)j * d->nx + i;
            if (!state[k]) continue;
            for (int q = 0; q < 8; q++) {
                long ii = (long)i + ring_di[q], jj = (long)j + ring_dj[q];
                if (ii < 0 || jj < 0 || ii >= d->nx || jj >= d->ny) continue;
                if (!state[(size_t)jj * d->nx + (size_t)ii]) {
                    state[k] = 2, ring[n_ring++] = k;
                    break;
                }
            }
        }
    while (n_ring) {
        for (size_t r = 0; r < n_ring; r++) {
            size_t k = ring[r];
            long i = (long)(k % d->nx), j = (long)(k / d->nx);
            double sum = 0, wsum = 0;
            for (int q = 0; q < 8; q++) {
                long ii = i + ring_di[q], jj = j + ring_dj[q];
                if (ii < 0 || jj < 0 || ii >= d->nx || jj >= d->ny) continue;
                size_t kk = (size_t)jj * d->nx + (size_t)ii;
                if (state[kk]) continue;
                sum += ring_w[q] * d->z[kk], wsum += ring_w[q];
            }
            value[r] = sum / wsum; /* a ring node touches a known node: wsum > 0 */
        }
        for (size_t r = 0; r < n_ring; r++) d->z[ring[r]] = value[r], state[ring[r]] = 0;
        *filled += n_ring;
        size_t n_next = 0;
        for (size_t r = 0; r < n_ring; r++) {
            size_t k = ring[r];
            long i = (long)(k % d->nx), j = (long)(k / d->nx);
            for (int q = 0; q < 8; q++) {
                long ii = i + ring_di[q], jj = j + ring_dj[q];
                if (ii < 0 || jj < 0 || ii >= d->nx || jj >= d->ny) continue;
                size_t kk = (size_t)jj * d->nx + (size_t)ii;
                if (state[kk] == 1) state[kk] = 2, next[n_next++] = kk;
            }
        }
        size_t *t = ring;
        ring = next, next = t, n_ring = n_next;
    }
done:
    free(state), free(ring), free(next), free(value);
    return rc;
}
