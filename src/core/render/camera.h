/* camera.h — the camera: position, orthonormal frame from the view direction and the up vector,
 * horizontal field of view (from focal length and sensor width when given). Pixel (0, 0) is the
 * top-left corner of the image.
 *
 * A perspective (pinhole) camera places the tangents of the angles off the view axis linearly
 * across and down the image. A cylindrical one (a panorama) turns the ray about the up axis by
 * an angle linear in x, a (x / width - 1/2) with a the field of view across, and places the
 * tangent of its elevation linearly in y, (1/2 - y / height) height a / width, which keeps
 * pixels square at the horizon; POV-Ray's `cylinder 1` camera is the same. A perspective
 * camera with radial distortion (k1, k2, the matched camera of a photomontage) bends its rays as
 * the photograph's lens did, through geometry/camera_project.h. */
#ifndef SYLVA_CAMERA_H
#define SYLVA_CAMERA_H

#include <stdint.h>

#include "geometry/camera_project.h"
#include "scene/scene_settings.h"
#include "util/vec3.h"

typedef struct camera {
    vec3 origin;
    vec3 forward, right, up; /* unit; right = forward x up */
    float tan_half_x, tan_half_y; /* perspective: tangents of the half fields of view */
    int cylindrical;
    float angle_x;           /* cylindrical: the field of view across, radians */
    float tan_range_y;       /* cylindrical: the tangent of the elevation spans [-this, this] */
    int distorted;           /* 1: perspective with radial distortion: rays through `model` */
    camera_model model;      /* the distorted camera (geometry/camera_project.h) */
    uint32_t width, height;
    float lens_radius;       /* metres: the thin lens's pupil (render/lens.h); 0: a pinhole */
    float focus_distance;    /* metres from the eye to the surface in sharp focus */
    float vignette;          /* strength of the cos^4 falloff, 0 to 1 */
} camera;

void camera_init(camera *c, const camera_settings *s, uint32_t width, uint32_t height);
/* Unit direction through image position (x, y) in pixels (continuous). */
vec3 camera_direction(const camera *c, float x, float y);

/* The smallest angle a pixel spans anywhere in the image, radians (at its corners). */
double camera_smallest_pixel_angle(const camera *c);

#endif
