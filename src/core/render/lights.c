/* lights.c — sun and sky set-up and sampling. */
#include "render/lights.h"

#include <math.h>
#include <string.h>

static void sky_eval_cb(const double dir[3], double rgb[3], const void *user)
{
    const lights *l = user;
    vec3 c = lights_sky(l, v3((float)dir[0], (float)dir[1], (float)dir[2]));
    rgb[0] = c.x, rgb[1] = c.y, rgb[2] = c.z;
}

vec3 lights_sky(const lights *l, vec3 dir)
{
    switch (l->sky_kind) {
    case SKY_PREETHAM: {
        double d[3] = {dir.x, dir.y, dir.z}, rgb[3];
        sky_preetham_radiance(&l->preetham, d, rgb);
        return v3((float)rgb[0], (float)rgb[1], (float)rgb[2]);
    }
    case SKY_CONSTANT: return l->sky_constant;
    case SKY_NONE: break;
    }
    return v3(0, 0, 0);
}

int lights_init(lights *l, const sun_settings *sun, const sky_settings *sky, err_buf *err)
{
    memset(l, 0, sizeof *l);
    l->sun_on = sun->enabled && sun->irradiance > 0;
    l->sun_dir = v3_norm(v3((float)sun->direction[0], (float)sun->direction[1], (float)sun->direction[2]));
    l->sun_irradiance = v3_scale(v3((float)sun->color[0], (float)sun->color[1], (float)sun->color[2]),
                                 (float)sun->irradiance);
    double half = sun->angular_diameter_deg * M_PI / 360.0;
    if (half > 1e-7) {
        l->cos_half = (float)cos(half);
        l->solid_angle = (float)(2.0 * M_PI * (1.0 - cos(half)));
        l->sun_radiance = v3_scale(l->sun_irradiance, (float)(1.0 / (M_PI * sin(half) * sin(half))));
    } else {
        l->cos_half = 1.0f;
        l->solid_angle = 0.0f;
    }
    v3_basis(l->sun_dir, &l->sun_t, &l->sun_b);
    l->ambient = v3((float)sky->ambient[0], (float)sky->ambient[1], (float)sky->ambient[2]);
    l->sky_kind = sky->model;
    l->sky_constant = v3_scale(v3((float)sky->color[0], (float)sky->color[1], (float)sky->color[2]), (float)sky->scale);
    if (sky->model == SKY_PREETHAM) {
        double d[3] = {l->sun_dir.x, l->sun_dir.y, l->sun_dir.z};
        if (sky_preetham_init(&l->preetham, d, sky->turbidity, sky->scale, sky->ground_albedo))
            return err_set(err, "sky: turbidity %g is outside the Preetham model's range [1.7, 10]", sky->turbidity);
    }
    if (sky->model != SKY_NONE) {
        if (sky_table_build(&l->table, 64, 128, sky_eval_cb, l)) return err_nomem(err, "out of memory for the sky table");
        /* mean over the upper hemisphere, from the table's cells */
        double sum[3] = {0, 0, 0}, wsum = 0;
        for (uint32_t r = 0; r < l->table.nt / 2; r++) {
            double th = (r + 0.5) * M_PI / l->table.nt, w = sin(th);
            for (uint32_t c = 0; c < l->table.np; c++)
                for (int k = 0; k < 3; k++) sum[k] += w * l->table.rgb[((size_t)r * l->table.np + c) * 3 + k];
            wsum += w * l->table.np;
        }
        l->sky_mean = v3((float)(sum[0] / wsum), (float)(sum[1] / wsum), (float)(sum[2] / wsum));
    }
    return 0;
}

void lights_free(lights *l) { sky_table_free(&l->table); }

float lights_sun_sample(const lights *l, float u1, float u2, vec3 *wi)
{
    if (l->solid_angle <= 0.0f) {
        *wi = l->sun_dir;
        return 1.0f;
    }
    float cz = 1.0f - u1 * (1.0f - l->cos_half);
    float sz = sqrtf(fmaxf(0.0f, 1.0f - cz * cz)), phi = 2.0f * (float)M_PI * u2;
    *wi = v3_norm(v3_add(v3_add(v3_scale(l->sun_t, sz * cosf(phi)), v3_scale(l->sun_b, sz * sinf(phi))),
                         v3_scale(l->sun_dir, cz)));
    return 1.0f / l->solid_angle;
}

int lights_in_sun(const lights *l, vec3 dir)
{
    return l->sun_on && l->solid_angle > 0.0f && v3_dot(dir, l->sun_dir) >= l->cos_half;
}
