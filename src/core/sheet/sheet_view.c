/* sheet_view.c — the facts a sheet states of a viewpoint in a frame (sheet_view.h). */
#include "sheet/sheet_view.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "geometry/camera_frame.h"
#include "render/camera.h"

#define DEG (M_PI / 180.0)

void sheet_local_time(const char *given, char *out, size_t n)
{
    out[0] = '\0';
    if (!given || !given[0]) return;
    const char *t = strchr(given, 'T'), *zone = t ? t + 1 : NULL;
    while (zone && *zone && *zone != 'Z' && *zone != '+' && *zone != '-') zone++;
    if (!t || !zone) return (void)snprintf(out, n, "%s", given);
    int date_len = (int)(t - given), time_len = (int)(zone - t - 1);
    if (*zone == 'Z') snprintf(out, n, "%.*s %.*s (UTC)", date_len, given, time_len, t + 1);
    else if (strlen(zone) == 3) snprintf(out, n, "%.*s %.*s (UTC%s:00)", date_len, given, time_len, t + 1, zone);
    else if (!strchr(zone, ':') && strlen(zone) == 5)
        snprintf(out, n, "%.*s %.*s (UTC%.3s:%s)", date_len, given, time_len, t + 1, zone, zone + 3);
    else snprintf(out, n, "%.*s %.*s (UTC%s)", date_len, given, time_len, t + 1, zone);
}

/* The nearest development object by its placement point, horizontally from the eye. */
static void nearest_development(const scene_file *sf, const double eye[3], sheet_view *out)
{
    out->nearest = NULL, out->distance_m = out->bearing_deg = NAN, out->structures = 0;
    for (uint32_t k = 0; k < sf->n_objects; k++) {
        const object_spec *o = &sf->objects[k];
        if (!o->development) continue;
        out->structures++;
        double dx = o->position[0] - eye[0], dy = o->position[1] - eye[1], d = hypot(dx, dy);
        if (out->nearest && !(d < out->distance_m)) continue;
        out->nearest = o->name ? o->name : "(unnamed)";
        out->development = (uint32_t)o->development <= sf->n_developments ? sf->developments[o->development - 1] : NULL;
        out->distance_m = d;
        out->bearing_deg = fmod(atan2(dx, dy) / DEG + 360.0, 360.0);
    }
}

/* The development's extent in the frame's angles, and whether the frame holds it. */
static void development_extent(const scene *s, const camera_settings *c, uint32_t w, uint32_t h, sheet_view *out)
{
    double f[3], r[3], u[3];
    camera_frame(c, f, r, u);
    camera cam;
    camera_init(&cam, c, w, h);
    out->dev_left_deg = out->dev_low_deg = INFINITY, out->dev_right_deg = out->dev_high_deg = -INFINITY;
    out->development_fits = 1;
    for (uint32_t o = 0; o < s->n_objects; o++) {
        if (!s->objects[o].development) continue;
        double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        scene_object_bounds(s, o, lo, hi);
        if (!(lo[0] <= hi[0])) continue;
        for (int k = 0; k < 8; k++) {
            double p[3] = {k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]}, d[3];
            for (int i = 0; i < 3; i++) d[i] = p[i] - c->position[i];
            double df = d[0] * f[0] + d[1] * f[1] + d[2] * f[2], dr = d[0] * r[0] + d[1] * r[1] + d[2] * r[2],
                   du = d[0] * u[0] + d[1] * u[1] + d[2] * u[2];
            double across = atan2(dr, df) / DEG, up = atan2(du, hypot(df, dr)) / DEG;
            out->dev_left_deg = fmin(out->dev_left_deg, across), out->dev_right_deg = fmax(out->dev_right_deg, across);
            out->dev_low_deg = fmin(out->dev_low_deg, up), out->dev_high_deg = fmax(out->dev_high_deg, up);
            int inside = cam.cylindrical
                             ? fabs(across * DEG) <= 0.5 * cam.angle_x && fabs(du / hypot(df, dr)) <= cam.tan_range_y
                             : df > 0 && fabs(dr / df) <= cam.tan_half_x && fabs(du / df) <= cam.tan_half_y;
            out->development_fits &= inside;
        }
    }
}

static void lens_of(const camera_settings *c, uint32_t w, uint32_t h, sheet_view *out)
{
    out->cylindrical = c->cylindrical;
    out->hfov_deg = c->fov_deg;
    double half = 0.5 * c->fov_deg * DEG;
    if (c->cylindrical) {
        out->vfov_deg = 2.0 * atan(0.5 * (double)h / w * c->fov_deg * DEG) / DEG;
        out->focal_mm = out->sensor_mm = out->focal35_mm = NAN;
        return;
    }
    out->vfov_deg = 2.0 * atan(tan(half) * h / w) / DEG;
    out->sensor_mm = c->sensor_width_mm > 0 ? c->sensor_width_mm : 36.0;
    out->focal_mm = c->focal_length_mm > 0 ? c->focal_length_mm : out->sensor_mm / (2.0 * tan(half));
    out->focal35_mm = out->focal_mm * 36.0 / out->sensor_mm;
}

void sheet_view_of(const scene *s, const scene_file *sf, const scene_viewpoint *v, const camera_settings *c,
                   const char *frame, uint32_t width, uint32_t height, sheet_view *out)
{
    memset(out, 0, sizeof *out);
    out->number = v ? scene_file_viewpoint_number(sf, v) : 0, out->name = v ? v->name : NULL, out->frame = frame;
    out->crs_name = s->site.crs_wkt ? s->site.crs_name : NULL;
    out->easting = c->position[0] + s->site.origin[0], out->northing = c->position[1] + s->site.origin[1];
    double ground;
    out->ground_level = scene_surveyed_height(s, c->position[0], c->position[1], &ground) ? NAN
                                                                                            : ground + s->site.origin[2];
    out->eye_height = c->eye_ground.given ? c->eye_ground.above : c->position[2] + s->site.origin[2] - out->ground_level;
    double f[3], r[3], u[3];
    camera_frame(c, f, r, u);
    out->heading_deg = fmod(atan2(f[0], f[1]) / DEG + 360.0, 360.0);
    out->pitch_deg = asin(fmax(-1.0, fmin(1.0, f[2]))) / DEG;
    nearest_development(sf, c->position, out);
    sheet_local_time(s->sun.date_time_local, out->local_time, sizeof out->local_time);
    out->sun_azimuth_deg = s->sun.azimuth_deg, out->sun_elevation_deg = s->sun.elevation_deg;
    out->width = width, out->height = height;
    lens_of(c, width, height, out);
    development_extent(s, c, width, height, out);
}
