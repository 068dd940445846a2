/* scene_probe.h — what is at one point of a scene's ground, in local metres: the terrain's height,
 * slope and aspect there (scene/heightfield.h, the surface plants and cameras stand on), whether
 * the terrain's water covers it, the plants standing within a radius (nearest first), and the
 * objects whose footprint — the outline of their triangles seen from above — covers it, and the
 * land-cover class of the nearest node when the scene has land cover. This is what `sylva probe`
 * prints.
 *
 * Ownership: a probe_result owns its two arrays; probe_result_free releases them.
 */
#ifndef SYLVA_SCENE_PROBE_H
#define SYLVA_SCENE_PROBE_H

#include <stdint.h>

#include "scene/scene.h"
#include "util/err.h"

typedef struct probe_plant {
    uint32_t instance;        /* index into scene.instances */
    uint32_t species;         /* index into scene.species */
    double position[3];       /* the plant's base, local metres */
    double height;            /* its model's height times its scale, metres */
    double distance;          /* horizontal, from the probed point, metres */
} probe_plant;

typedef struct probe_object {
    uint32_t object;          /* index into scene.objects */
    double top;               /* highest point of the object straight above the probed point */
} probe_object;

typedef struct probe_result {
    double x, y;              /* the probed point */
    double ground;            /* terrain height there */
    double slope_deg;         /* 0 level, 90 vertical */
    double aspect_deg;        /* compass direction the ground falls toward, clockwise from north;
                                 NAN where it is level */
    int water;                /* 1: below the terrain's water level */
    double water_level, water_depth; /* when water */
    int32_t land_class;       /* index into scene.land_cover->classes at the nearest node, or -1
                                 (no land cover, or no data there) */
    probe_plant *plants; uint32_t n_plants;   /* within the radius, nearest first; owned */
    probe_object *objects; uint32_t n_objects; /* in scene order; owned */
} probe_result;

/* Probes s at (x, y) with plants counted within `radius` metres. Returns 0, or -1 with err set:
 * ERR_INPUT when the scene has no terrain or (x, y) lies outside it (the sentence gives its
 * extent), ERR_NOMEM. r is zeroed first and may be freed in either case. */
int scene_probe(const scene *s, double x, double y, double radius, probe_result *r, err_buf *err);
void probe_result_free(probe_result *r); /* accepts a zeroed result */

#endif
