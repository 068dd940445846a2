/* light_summary.h — the scene's light as every back end sees it: the sun (a directional light
 * with an angular diameter: a uniform disc of radiance irradiance / (pi sin^2 theta_r) within
 * half-angle theta_r; a point-like sun when the diameter is 0) and the sky (Preetham, physical
 * with its aerial perspective, constant or none), with the two figures the verification mode and POV-Ray's export light by: the
 * constant ambient term and the sky's mean radiance over the upper hemisphere.
 *
 * The path tracer adds its sampling (render/lights.h) on top of this; the POV-Ray export and
 * the cross-check read it as it is, so every back end shows the same light.
 *
 * Ownership: a light_summary is a plain value; it holds no allocation.
 */
#ifndef SYLVA_LIGHT_SUMMARY_H
#define SYLVA_LIGHT_SUMMARY_H

#include "geometry/atmosphere.h"
#include "geometry/sky_preetham.h"
#include "scene/scene_settings.h"
#include "util/err.h"
#include "util/vec3.h"

/* The lat-long grid over the sphere (rows in theta from +Z, columns in phi from +X) whose cell
 * centres give the sky's mean; the path tracer tabulates its sky on the same grid. */
#define LIGHT_SKY_ROWS 64u
#define LIGHT_SKY_COLUMNS 128u

typedef struct light_summary {
    int sun_on;            /* sun.enabled and an irradiance above 0 */
    vec3 sun_dir;          /* unit, toward the sun */
    vec3 sun_irradiance;   /* RGB irradiance on a surface facing the sun */
    vec3 sun_radiance;     /* RGB radiance of the disc (0 for a point-like sun) */
    float cos_half;        /* cos of the disc's half angle; 1 for a point-like sun */
    float solid_angle;     /* of the disc; 0 for a point-like sun */

    sky_model sky_kind;
    sky_preetham preetham; /* SKY_PREETHAM */
    vec3 sky_constant;     /* SKY_CONSTANT radiance */
    atmosphere atmosphere; /* SKY_PHYSICAL */
    double origin_altitude;/* altitude above sea level of the scene's z = 0 (the site's origin) */
    /* The physical sky's air as constant fog, for the verification mode and POV-Ray's `fog`:
     * transmittance exp(-t / fog_distance) over a distance t, the rest fog_color; fog_distance
     * 0 for no fog (other skies, or no air). */
    double fog_distance;   /* 1 / (extinction at 550 nm at the camera), m */
    vec3 fog_color;        /* the horizon sky's mean over the azimuths */
    vec3 ambient;          /* the verification mode's constant ambient term (sky.ambient) */
    vec3 sky_mean;         /* mean sky radiance over the upper hemisphere (the LIGHT_SKY grid's
                              upper half, cells weighted by sin theta); 0 for no sky */
} light_summary;

/* origin_altitude is the altitude above sea level of the scene's z = 0 (site.origin[2], 0
 * without a site) and camera_z the camera's z: the physical sky is seen from their sum. threads:
 * for the physical sky's tables (atmosphere_init; 0: one per processor), the same for any count.
 * Returns 0, or -1 with err when the sky's settings are outside the model's range. */
int light_summary_init(light_summary *l, const sun_settings *sun, const sky_settings *sky, double origin_altitude,
                       double camera_z, unsigned threads, err_buf *err);

/* Sky radiance toward unit dir (the exact model). */
vec3 light_summary_sky(const light_summary *l, vec3 dir);

/* The fog over distance t (INFINITY: a ray that met nothing) applied to radiance L. */
vec3 light_summary_fog(const light_summary *l, vec3 L, float t);

#endif
