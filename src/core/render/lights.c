/* lights.c — the light summary plus the sun's sampling basis and the sky's sampling table. */
#include "render/lights.h"

#include <math.h>
#include <string.h>

static void sky_eval_cb(const double dir[3], double rgb[3], const void *user)
{
    vec3 c = light_summary_sky(user, v3((float)dir[0], (float)dir[1], (float)dir[2]));
    rgb[0] = c.x, rgb[1] = c.y, rgb[2] = c.z;
}

int lights_init(lights *l, const sun_settings *sun, const sky_settings *sky, double origin_altitude, double camera_z,
                unsigned threads, err_buf *err)
{
    memset(l, 0, sizeof *l);
    if (light_summary_init(&l->summary, sun, sky, origin_altitude, camera_z, threads, err)) return -1;
    v3_basis(l->summary.sun_dir, &l->sun_t, &l->sun_b);
    if (sky->model != SKY_NONE &&
        sky_table_build(&l->table, LIGHT_SKY_ROWS, LIGHT_SKY_COLUMNS, sky_eval_cb, &l->summary))
        return err_nomem(err, "out of memory for the sky table");
    return 0;
}

void lights_free(lights *l) { sky_table_free(&l->table); }

float lights_sun_sample(const lights *l, float u1, float u2, vec3 *wi)
{
    const light_summary *s = &l->summary;
    if (s->solid_angle <= 0.0f) {
        *wi = s->sun_dir;
        return 1.0f;
    }
    float cz = 1.0f - u1 * (1.0f - s->cos_half);
    float sz = sqrtf(fmaxf(0.0f, 1.0f - cz * cz)), phi = 2.0f * (float)M_PI * u2;
    *wi = v3_norm(v3_add(v3_add(v3_scale(l->sun_t, sz * cosf(phi)), v3_scale(l->sun_b, sz * sinf(phi))),
                         v3_scale(s->sun_dir, cz)));
    return 1.0f / s->solid_angle;
}

int lights_in_sun(const lights *l, vec3 dir)
{
    const light_summary *s = &l->summary;
    return s->sun_on && s->solid_angle > 0.0f && v3_dot(dir, s->sun_dir) >= s->cos_half;
}
