/* vessel_polyline.c — checks and reads the per-order control polylines (004 §3.3). */
#include "vessel_polyline.h"

#include <math.h>

int vessel_polyline_set(vessel_polyline *p, const double *xy, uint32_t n, double x_max,
                        double y_min, double y_max, const char *name, plugin_err *err)
{
    if (n == 0 || !xy)
        return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, name, "'%s' has no points; give at least one [order, value] point",
                           name);
    if (n > VESSEL_POLYLINE_MAX_POINTS)
        return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, name, "'%s' has %u points; at most %u are allowed", name, n,
                           VESSEL_POLYLINE_MAX_POINTS);
    for (uint32_t i = 0; i < n; i++) {
        double x = xy[2 * i], y = xy[2 * i + 1];
        if (!isfinite(x) || x < 0 || x > x_max)
            return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, name, "'%s' point %u has order %g; orders run from 0 to %g",
                               name, i, x, x_max);
        if (i > 0 && x < xy[2 * i - 2])
            return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, name,
                               "'%s' point %u has order %g after %g; orders must not decrease "
                               "(an equal order makes a step)",
                               name, i, x, xy[2 * i - 2]);
        if (!isfinite(y) || y < y_min || y > y_max)
            return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, name, "'%s' point %u has value %g; values run from %g to %g",
                               name, i, y, y_min, y_max);
        p->x[i] = x;
        p->y[i] = y;
    }
    p->n = n;
    return 0;
}

double vessel_polyline_at(const vessel_polyline *p, double x)
{
    if (x < p->x[0]) return p->y[0];
    /* The last point at or before x; at a step that is the later of the two points. */
    uint32_t i = 0;
    while (i + 1 < p->n && p->x[i + 1] <= x) i++;
    if (i + 1 == p->n) return p->y[i];
    double t = (x - p->x[i]) / (p->x[i + 1] - p->x[i]);
    return p->y[i] + t * (p->y[i + 1] - p->y[i]);
}
