/* ground_cover_place.h — grass and herbs on the ground near the camera being rendered, so that
 * the foreground gives scale (docs/rendering.md, Ground cover).
 *
 * Tufts stand where the camera can see them (inside the view's frustum, a tuft's size of margin
 * round it), within a radius of the eye: the scene's `ground_cover.radius`, or by default the
 * distance at which a blade GROUND_COVER_BLADE_LENGTH long spans one pixel of the image being
 * rendered (focal length in pixels times the blade's length); beyond it the ground's texture
 * carries the look. Beyond 40 % of the radius the tufts thin out, to none at the radius.
 *
 * Placement is stratified: the ground is cut into square cells of 1/density square metres, each
 * holding one candidate at a jittered point, kept with the probability that the ground's kinds
 * give there (meadow all, forest floor a quarter, soil a tenth, scree a twentieth, rock, snow and
 * water none) times a falloff with slope (none from 55 degrees). Every number is a hash of the
 * scene seed and the cell, so the same scene and camera give the same tufts in any run. When the
 * count would pass `max_instances`, the radius shrinks until it fits (reported).
 *
 * The tufts are instances of the ground cover's prototypes (ground_cover_models.h) appended to
 * the scene's instances; the POV-Ray export writes them with the plants. */
#ifndef SYLVA_GROUND_COVER_PLACE_H
#define SYLVA_GROUND_COVER_PLACE_H

#include <stdint.h>

#include "geometry/ground_cover.h"
#include "scene/scene.h"
#include "scene/scene_settings.h"

typedef struct ground_cover_report {
    uint32_t instances;     /* tufts placed */
    double radius;          /* metres: the radius used */
    double pixel_radius;    /* metres: where a blade spans a pixel */
    int capped;             /* 1: the radius shrank to keep to max_instances */
} ground_cover_report;

/* The share of full meadow density that grows on ground of kinds w with unit normal n
 * (n[2] = cos slope), in [0, 1]. */
double ground_cover_density(const float w[GROUND_KINDS], const double n[3]);

/* Adds the ground cover for s's camera and an image width x height pixels, the candidates
 * shared out between up to `threads` threads (0: one per processor; the tufts are the same for
 * any count). Nothing when gc is disabled, its density or max_instances is 0, or s has no
 * terrain. Returns 0, or -1 with err set (out of memory). rep may be NULL. */
int ground_cover_add(scene *s, const ground_cover_settings *gc, uint32_t width, uint32_t height, unsigned threads,
                     ground_cover_report *rep, err_buf *err);

#endif
