/* camera.c — primary ray directions. The frame (with its roll) is built in double precision
 * from the scene's numbers (geometry/camera_frame.h) and only the unit vectors are rounded to
 * float, so a look_at far away (or very close) still gives a finite frame; the scene loader
 * refuses what cannot be aimed at all. */
#include "render/camera.h"

#include <math.h>

#include "geometry/camera_frame.h"

static vec3 to_float(const double v[3]) { return v3((float)v[0], (float)v[1], (float)v[2]); }

void camera_init(camera *c, const camera_settings *s, uint32_t width, uint32_t height)
{
    c->origin = to_float(s->position);
    double f[3], r[3], u[3];
    camera_frame(s, f, r, u);
    c->forward = to_float(f);
    c->right = to_float(r);
    c->up = v3_cross(c->right, c->forward);
    c->width = width, c->height = height;
    c->cylindrical = s->cylindrical;
    c->angle_x = (float)(s->fov_deg * M_PI / 180.0);
    c->tan_range_y = c->angle_x * 0.5f * (float)height / (float)width;
    c->tan_half_x = c->cylindrical ? 0.0f : tanf((float)(s->fov_deg * M_PI / 360.0));
    c->tan_half_y = c->tan_half_x * (float)height / (float)width;
    c->distorted = !c->cylindrical && (s->k1 != 0.0 || s->k2 != 0.0);
    c->lens_radius = (float)camera_lens_radius(s);
    c->focus_distance = (float)s->focus_distance;
    c->vignette = (float)s->vignette;
    if (c->distorted) {
        camera_model_from_settings(&c->model, s, width, height);
        c->model.k1 = s->k1, c->model.k2 = s->k2;
    }
}

double camera_smallest_pixel_angle(const camera *c)
{
    if (c->cylindrical) {
        /* across: angle_x / width everywhere; down: d(atan t) = dt / (1 + t^2), smallest at the edge */
        double t = c->tan_range_y;
        return (double)c->angle_x / c->width / (1.0 + t * t);
    }
    /* A pixel spans 2 tan(fov/2) / width radians at the centre of the image and shrinks toward
     * its corners by 1 / (1 + x^2 + y^2) (x, y the tangents of the corner). */
    double tx = c->tan_half_x, ty = c->tan_half_y;
    return 2.0 * tx / c->width / (1.0 + tx * tx + ty * ty);
}

vec3 camera_direction(const camera *c, float x, float y)
{
    if (c->cylindrical) {
        float a = (x / (float)c->width - 0.5f) * c->angle_x;
        float t = (1.0f - 2.0f * y / (float)c->height) * c->tan_range_y;
        return v3_norm(v3_add(v3_add(v3_scale(c->forward, cosf(a)), v3_scale(c->right, sinf(a))), v3_scale(c->up, t)));
    }
    if (c->distorted) {
        double ray[3];
        /* where the lens folds the image (far outside any real photograph) the ray is the axis */
        if (camera_unproject(&c->model, x, y, ray)) return c->forward;
        return v3((float)ray[0], (float)ray[1], (float)ray[2]);
    }
    float sx = (2.0f * x / (float)c->width - 1.0f) * c->tan_half_x;
    float sy = (1.0f - 2.0f * y / (float)c->height) * c->tan_half_y;
    return v3_norm(v3_add(c->forward, v3_add(v3_scale(c->right, sx), v3_scale(c->up, sy))));
}
