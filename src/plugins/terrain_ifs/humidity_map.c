/* humidity_map.c — reading and resampling a humidity raster onto the output grid. */
#include "humidity_map.h"

#include <math.h>
#include <stdlib.h>

#include "raster_gdal.h"
#include "sylva/plugin.h"

/* Pixel coordinate (centres at k + 0.5 of `pixels` across [0, 1]) of a node at fraction t. */
static double pixel_of(double t, uint32_t pixels, uint32_t *p0, uint32_t *p1)
{
    double p = t * pixels - 0.5;
    if (p < 0) p = 0;
    if (p > pixels - 1.0) p = pixels - 1.0;
    *p0 = (uint32_t)p;
    *p1 = *p0 + 1 < pixels ? *p0 + 1 : *p0;
    return p - *p0;
}

int ifs_humidity_read(const ifs_humidity_source *src, uint32_t nx, uint32_t ny, float *out,
                      plugin_err *err)
{
    if (src->has_range && !(src->range[0] != src->range[1]))
        return plugin_fail(err, SYLVA_ERR_PARAM,
                        "the humidity range [%g, %g] is empty; give the raw values of humidity 0 "
                        "and of humidity 1", src->range[0], src->range[1]);
    ifs_raster r;
    int rc = ifs_raster_open(src->path, src->band ? src->band : 1, "humidity map", &r, err);
    if (rc) return rc;
    float *map = NULL;
    double *row = NULL;
    if ((uint64_t)r.cols * r.rows > IFS_HUMIDITY_MAX_PIXELS || r.cols < 1 || r.rows < 1) {
        rc = plugin_fail(err, SYLVA_ERR_LIMIT,
                      "the humidity map '%s' has %u x %u pixels; 1 to %u pixels are read",
                      src->path, r.cols, r.rows, IFS_HUMIDITY_MAX_PIXELS);
        goto done;
    }
    map = malloc((size_t)r.cols * r.rows * sizeof *map); /* owned here; row 0 north */
    row = malloc((size_t)r.cols * sizeof *row);
    if (!map || !row) {
        rc = plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory reading the humidity map '%s'",
                      src->path);
        goto done;
    }
    double lo = 0.0, hi = r.type_max > 0 ? r.type_max : 1.0;
    if (src->has_range) lo = src->range[0], hi = src->range[1];
    for (uint32_t y = 0; y < r.rows; y++) {
        if ((rc = ifs_raster_read_row(&r, y, 0, r.cols, row, "humidity map", err))) {
            plugin_err inner = *err;
            rc = plugin_fail(err, rc, "'%s': %s", src->path, inner.msg);
            goto done;
        }
        for (uint32_t x = 0; x < r.cols; x++) {
            double h = isnan(row[x]) ? 1.0 : (row[x] - lo) / (hi - lo);
            map[(size_t)y * r.cols + x] = (float)(h < 0 ? 0 : h > 1 ? 1 : h);
        }
    }
    for (uint32_t j = 0; j < ny; j++) {
        uint32_t y0, y1;
        double fy = pixel_of(1.0 - (double)j / (ny - 1), r.rows, &y0, &y1);
        const float *a = map + (size_t)y0 * r.cols, *b = map + (size_t)y1 * r.cols;
        for (uint32_t i = 0; i < nx; i++) {
            uint32_t x0, x1;
            double fx = pixel_of((double)i / (nx - 1), r.cols, &x0, &x1);
            double north = a[x0] + fx * (a[x1] - a[x0]), south = b[x0] + fx * (b[x1] - b[x0]);
            out[(size_t)j * nx + i] = (float)(north + fy * (south - north));
        }
    }
done:
    free(map), free(row);
    ifs_raster_close(&r);
    return rc;
}
