/* lights.h — the path tracer's lights: the scene's light summary (geometry/light_summary.h: sun
 * and sky) with what sampling needs on top: a basis around the sun for sampling its cone, and
 * the sky tabulated on the LIGHT_SKY grid for importance sampling.
 *
 * Ownership: lights owns its sky table (lights_free). */
#ifndef SYLVA_LIGHTS_H
#define SYLVA_LIGHTS_H

#include "geometry/light_summary.h"
#include "render/sky_table.h"
#include "scene/scene_settings.h"
#include "util/err.h"
#include "util/vec3.h"

typedef struct lights {
    light_summary summary;
    vec3 sun_t, sun_b;     /* basis around summary.sun_dir for cone sampling */
    sky_table table;       /* for sampling (empty for SKY_NONE) */
} lights;

/* The lights of these settings (light_summary_init's arguments, threads included); 0, or -1 with
 * err set. The caller frees them (lights_free), after a failure too. */
int lights_init(lights *l, const sun_settings *sun, const sky_settings *sky, double origin_altitude, double camera_z,
                unsigned threads, err_buf *err);
void lights_free(lights *l);

/* Samples a direction in the sun's cone; returns its pdf (1 for a point-like sun, i.e. a delta). */
float lights_sun_sample(const lights *l, float u1, float u2, vec3 *wi);
/* 1 when dir falls in the sun's disc. */
int lights_in_sun(const lights *l, vec3 dir);

#endif
