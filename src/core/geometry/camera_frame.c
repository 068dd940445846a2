/* camera_frame.c — the camera's frame with its roll (camera_frame.h). */
#include "geometry/camera_frame.h"

#include <math.h>

/* v scaled to unit length without overflow or underflow; zero stays zero. */
static void unit(double v[3])
{
    double m = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
    if (!(m > 0.0) || !isfinite(m)) return;
    for (int k = 0; k < 3; k++) v[k] /= m;
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; k++) v[k] /= l;
}

static void cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

void camera_frame(const camera_settings *s, double forward[3], double right[3], double up[3])
{
    double u[3] = {s->up[0], s->up[1], s->up[2]}, r[3], v[3];
    for (int k = 0; k < 3; k++)
        forward[k] = s->has_look_at ? s->look_at[k] - s->position[k] : s->direction[k];
    unit(forward);
    unit(u);
    cross(forward, u, r);
    unit(r);
    cross(r, forward, v);
    unit(v);
    double a = s->roll_deg * M_PI / 180.0, c = cos(a), sn = sin(a);
    if (s->roll_deg == 0.0) c = 1.0, sn = 0.0; /* exactly the unrolled frame */
    for (int k = 0; k < 3; k++) {
        up[k] = c * v[k] + sn * r[k];    /* the top of the camera leans to its right */
        right[k] = c * r[k] - sn * v[k];
    }
}

double camera_lens_radius(const camera_settings *s)
{
    if (!(s->f_number > 0.0)) return 0.0;
    double fov = s->fov_deg * M_PI / 180.0;
    double focal_m = s->focal_length_mm > 0.0 ? s->focal_length_mm * 1e-3
                     : s->cylindrical         ? s->sensor_width_mm * 1e-3 / fov
                                              : s->sensor_width_mm * 1e-3 / (2.0 * tan(fov / 2.0));
    return focal_m / (2.0 * s->f_number);
}
