/* lens.c — thin-lens rays and the natural vignette (lens.h). */
#include "render/lens.h"

#include <math.h>

/* Shirley and Chiu's concentric map of the unit square onto the unit disk (uniform area). */
static void concentric_disk(float u1, float u2, float *x, float *y)
{
    float a = 2.0f * u1 - 1.0f, b = 2.0f * u2 - 1.0f, r, phi;
    if (a == 0.0f && b == 0.0f) {
        *x = *y = 0.0f;
        return;
    }
    if (fabsf(a) > fabsf(b)) {
        r = a, phi = (float)M_PI_4 * (b / a);
    } else {
        r = b, phi = (float)M_PI_2 - (float)M_PI_4 * (a / b);
    }
    *x = r * cosf(phi), *y = r * sinf(phi);
}

/* The cosine of the angle off the axis that the vignette and the focus surface measure. */
static float axis_cosine(const camera *c, vec3 d)
{
    if (c->cylindrical) {
        float s = v3_dot(d, c->up);
        return sqrtf(fmaxf(0.0f, 1.0f - s * s));
    }
    return v3_dot(d, c->forward);
}

void lens_ray(const camera *c, float u1, float u2, vec3 *o, vec3 *d)
{
    float cosine = fmaxf(axis_cosine(c, *d), 1e-6f);
    vec3 focus = v3_madd(c->origin, *d, c->focus_distance / cosine);
    vec3 across = c->right;
    if (c->cylindrical) {
        vec3 h = v3_cross(*d, c->up);
        across = v3_dot(h, h) > 1e-12f ? v3_norm(h) : c->right;
    }
    float x, y;
    concentric_disk(u1, u2, &x, &y);
    *o = v3_add(c->origin, v3_add(v3_scale(across, x * c->lens_radius), v3_scale(c->up, y * c->lens_radius)));
    *d = v3_norm(v3_sub(focus, *o));
}

float lens_vignette(const camera *c, vec3 d)
{
    if (!(c->vignette > 0.0f)) return 1.0f;
    float k = fmaxf(axis_cosine(c, d), 0.0f), k2 = k * k;
    return 1.0f - c->vignette + c->vignette * k2 * k2;
}
