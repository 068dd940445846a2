/* dtm.c — creating, sizing and measuring DTM grids. */
#include "dtm.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sylva/plugin.h"

int ifs_dtm_check_size(uint32_t nx, uint32_t ny, plugin_err *err)
{
    if (nx < IFS_DTM_MIN_SIDE || ny < IFS_DTM_MIN_SIDE)
        return plugin_fail(err, SYLVA_ERR_PARAM,
                        "the DTM has %u x %u nodes; the IFS needs at least %u x %u (two cells along "
                        "each axis, so that every map shrinks the grid onto one cell)",
                        nx, ny, IFS_DTM_MIN_SIDE, IFS_DTM_MIN_SIDE);
    if (nx > IFS_DTM_MAX_SIDE || ny > IFS_DTM_MAX_SIDE)
        return plugin_fail(err, SYLVA_ERR_LIMIT,
                        "the DTM has %u x %u nodes; at most %u are interpolated along a side: crop "
                        "it or raise the resampling step", nx, ny, IFS_DTM_MAX_SIDE);
    return SYLVA_OK;
}

int ifs_dtm_new(uint32_t nx, uint32_t ny, double dx, double dy, ifs_dtm **out, plugin_err *err)
{
    *out = NULL;
    int rc = ifs_dtm_check_size(nx, ny, err);
    if (rc) return rc;
    if (!(dx > 0 && dy > 0 && isfinite(dx) && isfinite(dy)))
        return plugin_fail(err, SYLVA_ERR_PARAM,
                        "the DTM node spacing is %g x %g m; both must be positive finite numbers",
                        dx, dy);
    ifs_dtm *d = malloc(sizeof *d);                              /* owned by the caller */
    double *z = calloc((size_t)nx * ny, sizeof *z);               /* owned by d */
    if (!d || !z) {
        free(d), free(z);
        return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for a %u x %u DTM", nx, ny);
    }
    *d = (ifs_dtm){.nx = nx, .ny = ny, .dx = dx, .dy = dy, .z = z};
    *out = d;
    return SYLVA_OK;
}

void ifs_dtm_free(ifs_dtm *d)
{
    if (!d) return;
    free(d->z);
    free(d);
}

int ifs_dtm_from_rows(const double *rows, uint32_t cols, uint32_t nrows, double dx, double dy,
                      ifs_dtm **out, plugin_err *err)
{
    int rc = ifs_dtm_new(cols, nrows, dx, dy, out, err);
    if (rc) return rc;
    memcpy((*out)->z, rows, (size_t)cols * nrows * sizeof *rows);
    return SYLVA_OK;
}

void ifs_dtm_range(const ifs_dtm *d, double *zmin, double *zmax)
{
    double lo = INFINITY, hi = -INFINITY;
    for (size_t k = 0; k < (size_t)d->nx * d->ny; k++) {
        double z = d->z[k];
        if (!isfinite(z)) continue;
        if (z < lo) lo = z;
        if (z > hi) hi = z;
    }
    if (lo > hi) lo = hi = 0.0;
    *zmin = lo, *zmax = hi;
}
