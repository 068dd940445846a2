/* camera.c — primary ray directions. */
#include "render/camera.h"

#include <math.h>

void camera_init(camera *c, const camera_settings *s, uint32_t width, uint32_t height)
{
    c->origin = v3((float)s->position[0], (float)s->position[1], (float)s->position[2]);
    vec3 f;
    if (s->has_look_at)
        f = v3((float)(s->look_at[0] - s->position[0]), (float)(s->look_at[1] - s->position[1]),
               (float)(s->look_at[2] - s->position[2]));
    else
        f = v3((float)s->direction[0], (float)s->direction[1], (float)s->direction[2]);
    c->forward = v3_norm(f);
    vec3 up = v3_norm(v3((float)s->up[0], (float)s->up[1], (float)s->up[2]));
    c->right = v3_norm(v3_cross(c->forward, up));
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
