/* light_summary.c — the sun and sky from the scene's settings, and the sky's mean over the upper
 * hemisphere (see light_summary.h). */
#include "geometry/light_summary.h"

#include <math.h>
#include <string.h>

vec3 light_summary_sky(const light_summary *l, vec3 dir)
{
    switch (l->sky_kind) {
    case SKY_PREETHAM: {
        double d[3] = {dir.x, dir.y, dir.z}, rgb[3];
        sky_preetham_radiance(&l->preetham, d, rgb);
        return v3((float)rgb[0], (float)rgb[1], (float)rgb[2]);
    }
    case SKY_PHYSICAL: {
        double d[3] = {dir.x, dir.y, dir.z}, rgb[3];
        atmosphere_sky(&l->atmosphere, d, rgb);
        return v3((float)rgb[0], (float)rgb[1], (float)rgb[2]);
    }
    case SKY_CONSTANT: return l->sky_constant;
    case SKY_NONE: break;
    }
    return v3(0, 0, 0);
}

vec3 light_summary_fog(const light_summary *l, vec3 L, float t)
{
    if (!(l->fog_distance > 0.0)) return L;
    float T = isinf(t) ? 0.0f : (float)exp(-t / l->fog_distance);
    return v3_add(v3_scale(L, T), v3_scale(l->fog_color, 1.0f - T));
}

/* The horizon sky averaged over FOG_AZIMUTHS equally spaced azimuths. */
#define FOG_AZIMUTHS 72
static vec3 horizon_mean(const light_summary *l)
{
    double sum[3] = {0, 0, 0};
    for (int a = 0; a < FOG_AZIMUTHS; a++) {
        double phi = (a + 0.5) * (2.0 * M_PI / FOG_AZIMUTHS);
        vec3 c = light_summary_sky(l, v3((float)cos(phi), (float)sin(phi), 0.0f));
        sum[0] += c.x, sum[1] += c.y, sum[2] += c.z;
    }
    return v3((float)(sum[0] / FOG_AZIMUTHS), (float)(sum[1] / FOG_AZIMUTHS), (float)(sum[2] / FOG_AZIMUTHS));
}

/* The mean over the upper half of the LIGHT_SKY grid: each cell's radiance at its centre, as a
 * float (as the path tracer's table holds it), weighted by sin theta at the cell's centre row. */
static vec3 sky_mean(const light_summary *l)
{
    const uint32_t nt = LIGHT_SKY_ROWS, np = LIGHT_SKY_COLUMNS;
    double dtheta = M_PI / nt, dphi = 2.0 * M_PI / np;
    double sum[3] = {0, 0, 0}, wsum = 0;
    for (uint32_t r = 0; r < nt / 2; r++) {
        double theta = (r + 0.5) * dtheta, w = sin((r + 0.5) * M_PI / nt);
        for (uint32_t c = 0; c < np; c++) {
            double phi = (c + 0.5) * dphi;
            vec3 rgb = light_summary_sky(l, v3((float)(sin(theta) * cos(phi)), (float)(sin(theta) * sin(phi)),
                                               (float)cos(theta)));
            sum[0] += w * rgb.x, sum[1] += w * rgb.y, sum[2] += w * rgb.z;
        }
        wsum += w * np;
    }
    return v3((float)(sum[0] / wsum), (float)(sum[1] / wsum), (float)(sum[2] / wsum));
}

int light_summary_init(light_summary *l, const sun_settings *sun, const sky_settings *sky, double origin_altitude,
                       double camera_z, unsigned threads, err_buf *err)
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
    l->ambient = v3((float)sky->ambient[0], (float)sky->ambient[1], (float)sky->ambient[2]);
    l->sky_kind = sky->model;
    l->sky_constant = v3_scale(v3((float)sky->color[0], (float)sky->color[1], (float)sky->color[2]), (float)sky->scale);
    if (sky->model == SKY_PREETHAM) {
        double d[3] = {l->sun_dir.x, l->sun_dir.y, l->sun_dir.z};
        if (sky_preetham_init(&l->preetham, d, sky->turbidity, sky->scale, sky->ground_albedo))
            return err_set(err, "sky: turbidity %g is outside the Preetham model's range [1.7, 10]", sky->turbidity);
    }
    l->origin_altitude = origin_altitude;
    if (sky->model == SKY_PHYSICAL) {
        double d[3] = {l->sun_dir.x, l->sun_dir.y, l->sun_dir.z}, e[3];
        for (int k = 0; k < 3; k++) e[k] = sun->color[k] * sun->irradiance;
        double altitude = origin_altitude + camera_z;
        if (sky->visibility_km > atmosphere_clear_visibility_km(altitude))
            return err_fail(err, ERR_INPUT,
                            "sky: visibility %g km is longer than clean air allows at the camera's altitude "
                            "of %.0f m (%.0f km, Rayleigh scattering alone); give a shorter one",
                           sky->visibility_km, altitude, atmosphere_clear_visibility_km(altitude));
        if (atmosphere_init(&l->atmosphere, d, e, altitude, sky->visibility_km, sky->density, sky->scale,
                            sky->ground_albedo, threads))
            return err_fail(err, ERR_INPUT, "sky: the physical sky cannot be set up (visibility %g km, density %g)",
                            sky->visibility_km, sky->density);
        double beta = atmosphere_extinction_550(&l->atmosphere, altitude);
        if (beta > 0.0) {
            l->fog_distance = 1.0 / beta;
            l->fog_color = horizon_mean(l);
        }
    }
    if (sky->model != SKY_NONE) l->sky_mean = sky_mean(l);
    return 0;
}
