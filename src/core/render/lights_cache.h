/* lights_cache.h — the lights (render/lights.h) of several render setups built once: a study
 * renders many cameras under one sun, sky and season, and the sky's tables and the physical
 * sky's atmosphere take as long to build as a small frame to render. The cache keeps the lights
 * of the last inputs it was asked for and gives them again while the inputs are the same to the
 * bit: the sun, the sky, the site's altitude and, for the physical sky alone (seen from the
 * camera's altitude, light_summary.h), the camera's height. Any other sky is the same from every
 * camera, so its lights are built once for every viewpoint; the physical sky's once for the
 * frames of one viewpoint. What it gives is what lights_init builds from the same inputs.
 *
 * Ownership: the cache owns its lights (lights_cache_free). The lights it gives are borrowed:
 * they stay until the next lights_cache_get or lights_cache_free. One thread at a time. */
#ifndef SYLVA_LIGHTS_CACHE_H
#define SYLVA_LIGHTS_CACHE_H

#include "render/lights.h"

typedef struct lights_cache lights_cache;

/* A new, empty cache (lights_cache_free), or NULL when out of memory. */
lights_cache *lights_cache_new(void);
void lights_cache_free(lights_cache *c); /* accepts NULL */

/* The lights of these inputs (lights_init's), built on up to `threads` threads or kept (the
 * same lights for any count); NULL with err set when they cannot be built. */
const lights *lights_cache_get(lights_cache *c, const sun_settings *sun, const sky_settings *sky,
                               double origin_altitude, double camera_z, unsigned threads, err_buf *err);

#endif
