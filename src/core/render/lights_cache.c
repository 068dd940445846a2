/* lights_cache.c — the last lights built, kept while their inputs stay the same (lights_cache.h). */
#include "render/lights_cache.h"

#include <stdlib.h>
#include <string.h>

/* Every input lights_init reads, as numbers compared to the bit. */
enum { KEY_NUMBERS = 23 };

struct lights_cache {
    int built;                 /* 1: lt holds the lights of key */
    double key[KEY_NUMBERS];
    lights lt;                 /* owned (lights_free) */
};

/* The inputs as one array; the camera's height only where the sky depends on it. */
static void key_of(const sun_settings *sun, const sky_settings *sky, double origin_altitude, double camera_z,
                   double key[KEY_NUMBERS])
{
    double k[KEY_NUMBERS] = {sun->enabled, sun->direction[0], sun->direction[1], sun->direction[2],
                             sun->irradiance, sun->color[0], sun->color[1], sun->color[2],
                             sun->angular_diameter_deg, sky->model, sky->turbidity, sky->visibility_km,
                             sky->density, sky->scale, sky->color[0], sky->color[1], sky->color[2],
                             sky->ground_albedo, sky->ambient[0], sky->ambient[1], sky->ambient[2],
                             origin_altitude, sky->model == SKY_PHYSICAL ? camera_z : 0.0};
    memcpy(key, k, sizeof k);
}

lights_cache *lights_cache_new(void)
{
    return calloc(1, sizeof(lights_cache)); /* owned by the caller: lights_cache_free */
}

void lights_cache_free(lights_cache *c)
{
    if (!c) return;
    if (c->built) lights_free(&c->lt);
    free(c);
}

const lights *lights_cache_get(lights_cache *c, const sun_settings *sun, const sky_settings *sky,
                               double origin_altitude, double camera_z, unsigned threads, err_buf *err)
{
    double key[KEY_NUMBERS];
    key_of(sun, sky, origin_altitude, camera_z, key);
    if (c->built && !memcmp(key, c->key, sizeof key)) return &c->lt;
    if (c->built) lights_free(&c->lt);
    c->built = 0;
    if (lights_init(&c->lt, sun, sky, origin_altitude, camera_z, threads, err)) {
        lights_free(&c->lt);
        return NULL;
    }
    memcpy(c->key, key, sizeof key);
    c->built = 1;
    return &c->lt;
}
