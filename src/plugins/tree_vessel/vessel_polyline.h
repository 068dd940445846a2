/* vessel_polyline.h — the control polylines of the vessel model: a per-order parameter is given
 * as (order, value) points over the Gravelius order g in [0, 15] or the Weibull order w in
 * [0, 50] (004 §3.3, Fig. 3.5), and read at whole orders.
 *
 * Between two points the value is linear in the order; before the first point it is the first
 * value and past the last point the last value. Two points at the same order make a step: at
 * that order and past it the later point holds. */
#ifndef VESSEL_POLYLINE_H
#define VESSEL_POLYLINE_H

#include <stdint.h>

#include "plugin_err.h"

#define VESSEL_POLYLINE_MAX_POINTS 64u
#define VESSEL_ORDER_G_MAX 15u /* Gravelius orders the g polylines span */
#define VESSEL_ORDER_W_MAX 50u /* Weibull orders the w polylines span */

typedef struct vessel_polyline {
    uint32_t n;                           /* points, 1 .. VESSEL_POLYLINE_MAX_POINTS */
    double x[VESSEL_POLYLINE_MAX_POINTS]; /* orders, non-decreasing */
    double y[VESSEL_POLYLINE_MAX_POINTS]; /* values */
} vessel_polyline;

/* Fills p from n interleaved (x, y) pairs. Returns 0, or -1 with err set (param = name) when
 * there are no points, more than VESSEL_POLYLINE_MAX_POINTS, an order outside [0, x_max], an
 * order below its predecessor, a value outside [y_min, y_max] or a value that is not finite. */
int vessel_polyline_set(vessel_polyline *p, const double *xy, uint32_t n, double x_max,
                        double y_min, double y_max, const char *name, plugin_err *err);

/* The value at order x (any real; see the header comment for steps and the ends). */
double vessel_polyline_at(const vessel_polyline *p, double x);

#endif
