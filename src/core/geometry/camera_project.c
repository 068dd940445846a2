/* camera_project.c — world point to pixel and back through the distorted pinhole
 * (camera_project.h). The frame comes from camera_frame, so the projection and the renderer's rays
 * cannot disagree on how heading, pitch and roll aim the camera. */
#include "geometry/camera_project.h"

#include <math.h>
#include <string.h>

#include "geometry/camera_frame.h"

#define DEG (M_PI / 180.0)

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

double camera_model_focal_px(const camera_model *m)
{
    return (double)m->width / (2.0 * tan(m->fov_deg * DEG / 2.0));
}

void camera_model_set_focal_px(camera_model *m, double focal_px)
{
    m->fov_deg = 2.0 * atan((double)m->width / (2.0 * focal_px)) / DEG;
}

void camera_model_set_focal_mm(camera_model *m, double focal_mm, double sensor_width_mm)
{
    m->fov_deg = 2.0 * atan(sensor_width_mm / (2.0 * focal_mm)) / DEG;
}

double camera_model_focal_mm(const camera_model *m, double sensor_width_mm)
{
    return sensor_width_mm / (2.0 * tan(m->fov_deg * DEG / 2.0));
}

void camera_model_to_settings(const camera_model *m, camera_settings *s)
{
    memset(s, 0, sizeof *s);
    double h = m->heading_deg * DEG, e = m->pitch_deg * DEG;
    for (int k = 0; k < 3; k++) s->position[k] = m->position[k];
    s->direction[0] = sin(h) * cos(e), s->direction[1] = cos(h) * cos(e), s->direction[2] = sin(e);
    s->up[0] = -sin(h) * sin(e), s->up[1] = -cos(h) * sin(e), s->up[2] = cos(e);
    s->roll_deg = m->roll_deg;
    s->fov_deg = m->fov_deg;
}

void camera_model_frame(const camera_model *m, double forward[3], double right[3], double up[3])
{
    camera_settings s;
    camera_model_to_settings(m, &s);
    camera_frame(&s, forward, right, up);
}

void camera_model_from_settings(camera_model *m, const camera_settings *s, uint32_t width, uint32_t height)
{
    double f[3], r[3], u[3];
    camera_frame(s, f, r, u);
    *m = (camera_model){.fov_deg = s->fov_deg, .width = width, .height = height};
    for (int k = 0; k < 3; k++) m->position[k] = s->position[k];
    double horizontal = hypot(f[0], f[1]);
    m->pitch_deg = atan2(f[2], horizontal) / DEG;
    if (horizontal < 1e-12) {
        /* Straight up or down: the unrolled frame's up points along the heading (down) or
         * against it (up), so the heading is where the top of the image points; no roll. */
        double sign = f[2] < 0 ? 1.0 : -1.0;
        m->heading_deg = atan2(sign * u[0], sign * u[1]) / DEG;
        return;
    }
    m->heading_deg = atan2(f[0], f[1]) / DEG;
    /* The unrolled frame: right0 = forward x z (level), up0 = right0 x forward. */
    double r0[3] = {f[1] / horizontal, -f[0] / horizontal, 0.0};
    double u0[3] = {r0[1] * f[2] - r0[2] * f[1], r0[2] * f[0] - r0[0] * f[2], r0[0] * f[1] - r0[1] * f[0]};
    /* right = cos(roll) right0 - sin(roll) up0 (camera_frame.c) */
    m->roll_deg = atan2(-dot3(r, u0), dot3(r, r0)) / DEG;
}

int camera_project(const camera_model *m, const double p[3], double pixel[2])
{
    double f[3], r[3], u[3], d[3];
    camera_model_frame(m, f, r, u);
    for (int k = 0; k < 3; k++) d[k] = p[k] - m->position[k];
    double z = dot3(d, f);
    if (!(z > 0.0)) return -1;
    double x = dot3(d, r) / z, y = dot3(d, u) / z, r2 = x * x + y * y;
    double radial = 1.0 + r2 * (m->k1 + m->k2 * r2), fp = camera_model_focal_px(m);
    pixel[0] = 0.5 * m->width + fp * x * radial;
    pixel[1] = 0.5 * m->height - fp * y * radial;
    return 0;
}

/* The largest tangent-plane radius up to which rho(r) = r (1 + k1 r^2 + k2 r^4) grows: the first
 * positive root of rho'(r) = 1 + 3 k1 r^2 + 5 k2 r^4, or infinity. */
static double radius_of_fold(double k1, double k2)
{
    double s = INFINITY; /* s = r^2 */
    if (k2 == 0.0) {
        if (k1 < 0.0) s = -1.0 / (3.0 * k1);
    } else {
        double disc = 9.0 * k1 * k1 - 20.0 * k2;
        if (disc >= 0.0) {
            double sq = sqrt(disc);
            double a = (-3.0 * k1 - sq) / (10.0 * k2), b = (-3.0 * k1 + sq) / (10.0 * k2);
            if (a > 0.0) s = fmin(s, a);
            if (b > 0.0) s = fmin(s, b);
        }
    }
    return sqrt(s);
}

int camera_unproject(const camera_model *m, double x, double y, double ray[3])
{
    double fp = camera_model_focal_px(m);
    double xd = (x - 0.5 * m->width) / fp, yd = (0.5 * m->height - y) / fp;
    double rd = hypot(xd, yd), scale = 1.0;
    if (rd > 0.0 && (m->k1 != 0.0 || m->k2 != 0.0)) {
        /* rho is increasing on [0, fold]: Newton steps kept inside a shrinking bracket. */
        double lo = 0.0, hi = radius_of_fold(m->k1, m->k2);
        if (isfinite(hi)) {
            double top = hi * (1.0 + hi * hi * (m->k1 + m->k2 * hi * hi));
            if (rd > top) return -1;
        }
        double r = fmin(rd, isfinite(hi) ? hi : rd);
        for (int i = 0; i < 60; i++) {
            double r2 = r * r, rho = r * (1.0 + r2 * (m->k1 + m->k2 * r2)) - rd;
            double slope = 1.0 + r2 * (3.0 * m->k1 + 5.0 * m->k2 * r2);
            if (rho > 0.0) hi = r; else lo = r;
            double next = r - rho / slope;
            if (!(slope > 0.0) || !(next > lo && next < hi)) next = isfinite(hi) ? 0.5 * (lo + hi) : 2.0 * r;
            if (fabs(next - r) <= 1e-15 * fmax(r, 1e-300)) { r = next; break; }
            r = next;
        }
        scale = r / rd;
    }
    double tx = xd * scale, ty = yd * scale, f[3], rr[3], u[3];
    camera_model_frame(m, f, rr, u);
    for (int k = 0; k < 3; k++) ray[k] = f[k] + tx * rr[k] + ty * u[k];
    double l = sqrt(dot3(ray, ray));
    for (int k = 0; k < 3; k++) ray[k] /= l;
    return 0;
}
