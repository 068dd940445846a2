/* dtm_file.c — reading a DTM from a raster: window, step, units, nodata. */
#include "dtm_file.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "raster_gdal.h"
#include "sylva/plugin.h"

#define WGS84_A 6378137.0
#define WGS84_F (1.0 / 298.257223563)
#define IFS_MAX_ABS_LATITUDE 89.9 /* closer to a pole, a longitude degree has almost no width */
#define IFS_DEGREE_CELL_MAX 0.1   /* a unitless cell size at most this is read as degrees */

void ifs_metres_per_degree(double phi_deg, double *per_lon, double *per_lat)
{
    double e2 = WGS84_F * (2.0 - WGS84_F), phi = phi_deg * M_PI / 180.0, s = sin(phi);
    double w = sqrt(1.0 - e2 * s * s);
    double n = WGS84_A / w;                       /* prime-vertical radius of curvature */
    double m = WGS84_A * (1.0 - e2) / (w * w * w); /* meridional radius of curvature */
    *per_lon = n * cos(phi) * M_PI / 180.0;
    *per_lat = m * M_PI / 180.0;
}

/* The window to read: the crop (checked against the raster) trimmed so that the step lands on
 * its last node. */
static int dtm_window(const ifs_raster *r, const ifs_dtm_file_options *opt, const char *path,
                      uint32_t win[4], uint32_t *nx, uint32_t *ny, plugin_err *err)
{
    uint64_t c0 = 0, r0 = 0, cw = r->cols, rh = r->rows;
    if (opt->has_crop) {
        c0 = opt->crop[0], r0 = opt->crop[1], cw = opt->crop[2], rh = opt->crop[3];
        if (!cw || !rh || c0 + cw > r->cols || r0 + rh > r->rows)
            return plugin_fail(err, SYLVA_ERR_PARAM,
                            "the crop window [%llu, %llu, %llu, %llu] (first column, first row, "
                            "columns, rows) does not lie inside '%s', which has %u columns and %u "
                            "rows", (unsigned long long)c0, (unsigned long long)r0,
                            (unsigned long long)cw, (unsigned long long)rh, path, r->cols, r->rows);
    }
    uint32_t step = opt->step ? opt->step : 1;
    if (cw == 0 || rh == 0)
        return plugin_fail(err, SYLVA_ERR_PARAM, "the DTM '%s' has no pixels (%u x %u)", path,
                        r->cols, r->rows);
    *nx = (uint32_t)((cw - 1) / step + 1);
    *ny = (uint32_t)((rh - 1) / step + 1);
    int rc = ifs_dtm_check_size(*nx, *ny, err);
    if (rc) {
        plugin_err inner = *err;
        return plugin_fail(err, rc, "'%s' read from a %llu x %llu pixel window with step %u: %s", path,
                        (unsigned long long)cw, (unsigned long long)rh, step, inner.msg);
    }
    win[0] = (uint32_t)c0, win[1] = (uint32_t)r0;
    win[2] = (*nx - 1) * step + 1, win[3] = (*ny - 1) * step + 1;
    return SYLVA_OK;
}

/* Node spacing in metres and whether the grid was in degrees. */
static int dtm_spacing(const ifs_raster *r, const ifs_dtm_file_options *opt, const char *path,
                       const uint32_t win[4], double *dx, double *dy, ifs_dtm_file_info *info,
                       plugin_err *err)
{
    const double *t = r->transform;
    uint32_t step = opt->step ? opt->step : 1;
    double cx = win[0] + 0.5 * win[2], cy = win[1] + 0.5 * win[3]; /* window centre, pixels */
    info->centre_x = t[0] + cx * t[1] + cy * t[2];
    info->centre_y = t[3] + cx * t[4] + cy * t[5];
    /* node (0, 0) is the window's last row in a north-up raster, its first in a south-up one */
    double row0 = t[5] > 0 ? win[1] : win[1] + (double)(win[3] - 1);
    info->node0_x = t[0] + (win[0] + 0.5) * t[1] + (row0 + 0.5) * t[2];
    info->node0_y = t[3] + (win[0] + 0.5) * t[4] + (row0 + 0.5) * t[5];
    if (opt->cell_size[0] > 0 && opt->cell_size[1] > 0) {
        *dx = opt->cell_size[0], *dy = opt->cell_size[1];
        return SYLVA_OK;
    }
    if (!r->has_transform)
        return plugin_fail(err, SYLVA_ERR_PARAM,
                        "'%s' has no georeferencing, so its node spacing is unknown; give cell_size "
                        "in metres", path);
    if (t[2] != 0.0 || t[4] != 0.0)
        return plugin_fail(err, SYLVA_ERR_PARAM,
                        "'%s' is a rotated grid (geotransform terms %g and %g); only north-up or "
                        "south-up grids are read: warp it to a north-up grid first", path, t[2], t[4]);
    double sx = fabs(t[1]) * step, sy = fabs(t[5]) * step;
    if (!(sx > 0 && sy > 0 && isfinite(sx) && isfinite(sy)))
        return plugin_fail(err, SYLVA_ERR_PARAM, "'%s' has pixel size %g x %g; it must be non-zero",
                        path, t[1], t[5]);
    int degrees = 0;
    if (opt->units == IFS_UNITS_DEGREES) degrees = 1;
    else if (opt->units == IFS_UNITS_AUTO) {
        if (r->crs == IFS_CRS_GEOGRAPHIC) degrees = 1;
        else if (r->crs == IFS_CRS_NONE) {
            double x0 = t[0] + win[0] * t[1], x1 = t[0] + (win[0] + win[2]) * t[1];
            double y0 = t[3] + win[1] * t[5], y1 = t[3] + (win[1] + win[3]) * t[5];
            info->units_guessed = 1;
            degrees = fabs(t[1]) <= IFS_DEGREE_CELL_MAX && fabs(t[5]) <= IFS_DEGREE_CELL_MAX &&
                      fabs(x0) <= 180 && fabs(x1) <= 180 && fabs(y0) <= 90 && fabs(y1) <= 90;
        }
    }
    if (!degrees) {
        double u = opt->units == IFS_UNITS_AUTO ? r->metres_per_unit : 1.0;
        *dx = sx * u, *dy = sy * u;
        return SYLVA_OK;
    }
    double lat = info->centre_y;
    if (!(fabs(lat) < IFS_MAX_ABS_LATITUDE))
        return plugin_fail(err, SYLVA_ERR_PARAM,
                        "'%s' read as degrees has its centre at latitude %g; the conversion to "
                        "metres needs a latitude inside (-%g, %g): crop away from the pole, or set "
                        "units: metres if the grid is not in degrees", path, lat,
                        IFS_MAX_ABS_LATITUDE, IFS_MAX_ABS_LATITUDE);
    double per_lon, per_lat;
    ifs_metres_per_degree(lat, &per_lon, &per_lat);
    *dx = sx * per_lon, *dy = sy * per_lat;
    info->degrees = 1, info->centre_lat = lat;
    return SYLVA_OK;
}

/* Every height read lies in the plausible range: a corrupted file (heights of +-1e34, or a
 * nodata value the file does not declare) is refused instead of becoming a wall of terrain. */
static int dtm_check_heights(const ifs_dtm *d, const ifs_dtm_file_options *opt, const char *path,
                             plugin_err *err)
{
    double lo = opt->height_range[0], hi = opt->height_range[1];
    if (lo == 0.0 && hi == 0.0) lo = IFS_DTM_HEIGHT_MIN, hi = IFS_DTM_HEIGHT_MAX;
    for (uint32_t j = 0; j < d->ny; j++)
        for (uint32_t i = 0; i < d->nx; i++) {
            double z = d->z[(size_t)j * d->nx + i];
            if (isnan(z) || (z >= lo && z <= hi)) continue; /* NaN: nodata, filled later */
            return plugin_fail(err, SYLVA_ERR_PARAM,
                            "'%s' holds the height %g m at DTM node (%u, %u) (column from the "
                            "west, row from the south), outside the plausible range [%g, %g] m: "
                            "the file is damaged or has an undeclared nodata value; if the "
                            "heights are real, widen height_range", path, z, i, j, lo, hi);
        }
    return SYLVA_OK;
}

int ifs_dtm_read_file(const char *path, const ifs_dtm_file_options *opt, ifs_dtm **out,
                      ifs_dtm_file_info *info_out, plugin_err *err)
{
    *out = NULL;
    ifs_dtm_file_info info;
    memset(&info, 0, sizeof info);
    ifs_raster r;
    int rc = ifs_raster_open_in(path, opt->band ? opt->band : 1, "DTM", opt->target_wkt, &r, err);
    if (rc) return rc;
    memcpy(info.driver, r.driver, sizeof info.driver);
    memcpy(info.type_name, r.type_name, sizeof info.type_name);
    info.file_cols = r.cols, info.file_rows = r.rows;
    uint32_t win[4] = {0}, nx = 0, ny = 0, step = opt->step ? opt->step : 1;
    double dx = 0, dy = 0, *row = NULL;
    ifs_dtm *d = NULL;
    if ((rc = dtm_window(&r, opt, path, win, &nx, &ny, err))) goto done;
    if (opt->check_size && (rc = opt->check_size(opt->check_ctx, nx, ny, err))) goto done;
    if ((rc = dtm_spacing(&r, opt, path, win, &dx, &dy, &info, err))) goto done;
    if ((rc = ifs_dtm_new(nx, ny, dx, dy, &d, err))) goto done;
    row = malloc((size_t)win[2] * sizeof *row); /* owned here: one file row of the window */
    if (!row) {
        rc = plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory reading a row of '%s'", path);
        goto done;
    }
    /* DTM row 0 is the south edge: the file's last row of the window when the raster is
     * north-up (negative y pixel size, or no georeferencing: image order). File rows are read
     * in file order whatever the orientation: asked for the rows of a truncated ESRI ASCII grid
     * bottom-up, GDAL 3.6's reader works for minutes before it fails; top-down it stops at the
     * first missing row at once. */
    int south_up = r.has_transform && r.transform[5] > 0;
    for (uint32_t k = 0; k < ny; k++) {
        uint32_t j = south_up ? k : ny - 1 - k, file_row = win[1] + k * step;
        if ((rc = ifs_raster_read_row(&r, file_row, win[0], win[2], row, "DTM", err))) {
            plugin_err inner = *err;
            rc = plugin_fail(err, rc, "'%s': %s", path, inner.msg);
            goto done;
        }
        for (uint32_t i = 0; i < nx; i++) d->z[(size_t)j * nx + i] = row[(size_t)i * step];
    }
    if ((rc = dtm_check_heights(d, opt, path, err))) goto done;
    if ((rc = ifs_dtm_fill_nodata(d, &info.nodata_filled, err))) {
        plugin_err inner = *err;
        rc = plugin_fail(err, rc, "'%s': %s", path, inner.msg);
        goto done;
    }
    memcpy(info.window, win, sizeof win);
    *out = d, d = NULL;
    if (info_out) *info_out = info;
done:
    free(row);
    ifs_dtm_free(d);
    ifs_raster_close(&r);
    return rc;
}
