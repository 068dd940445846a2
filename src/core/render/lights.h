/* lights.h — the sun (a directional light with an angular diameter: a uniform disk of
 * radiance irradiance / (pi sin^2 theta_r) within half-angle theta_r; a point-like sun when the
 * diameter is 0) and the sky (Preetham, constant or none), tabulated for importance sampling.
 *
 * Ownership: lights owns its sky table (lights_free). */
#ifndef SYLVA_LIGHTS_H
#define SYLVA_LIGHTS_H

#include "render/sky.h"
#include "scene/scene_file.h"
#include "util/err.h"
#include "util/vec3.h"

typedef struct lights {
    int sun_on;
    vec3 sun_dir;          /* unit, toward the sun */
    vec3 sun_irradiance;   /* RGB irradiance on a surface facing the sun */
    vec3 sun_radiance;     /* RGB radiance of the disk */
    float cos_half;        /* cos of the half angle; 1 for a point-like sun */
    float solid_angle;     /* of the disk; 0 for a point-like sun */
    vec3 sun_t, sun_b;     /* basis around sun_dir for cone sampling */

    sky_model sky_kind;
    sky_preetham preetham;
    vec3 sky_constant;
    sky_table table;       /* for sampling (empty for SKY_NONE) */
    vec3 ambient;          /* verification mode */
    vec3 sky_mean;         /* mean sky radiance over the upper hemisphere (verification background) */
} lights;

int lights_init(lights *l, const sun_settings *sun, const sky_settings *sky, err_buf *err);
void lights_free(lights *l);

/* Sky radiance toward dir (exact model, not the table). */
vec3 lights_sky(const lights *l, vec3 dir);
/* Samples a direction in the sun's cone; returns its pdf (1 for a point-like sun, i.e. a delta). */
float lights_sun_sample(const lights *l, float u1, float u2, vec3 *wi);
/* 1 when dir falls in the sun's disk. */
int lights_in_sun(const lights *l, vec3 dir);

#endif
