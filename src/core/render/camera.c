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
    c->tan_half_x = tanf((float)(s->fov_deg * M_PI / 360.0));
    c->tan_half_y = c->tan_half_x * (float)height / (float)width;
}

vec3 camera_direction(const camera *c, float x, float y)
{
    float sx = (2.0f * x / (float)c->width - 1.0f) * c->tan_half_x;
    float sy = (1.0f - 2.0f * y / (float)c->height) * c->tan_half_y;
    return v3_norm(v3_add(c->forward, v3_add(v3_scale(c->right, sx), v3_scale(c->up, sy))));
}
