/* lens.h — what the lens adds to the pinhole camera (render/camera.h): depth of field through a
 * thin lens, and natural vignetting.
 *
 * Thin lens: the entrance pupil is a disk of radius f / (2 N) about the eye point (f the focal
 * length, N the f-number), across the view: spanned by the camera's right and up vectors, for a
 * panorama by the horizontal perpendicular to the ray and the up vector. The pinhole ray through
 * an image position meets the surface of sharp focus at P: a plane across the view axis at
 * focus_distance (perspective; also the distorted camera of a photomontage, whose rays bend
 * before the lens is applied), a cylinder of that radius about the up axis (panorama). The ray
 * leaves a point drawn uniformly on the pupil (Shirley and Chiu's concentric map) toward P, so
 * what lies at the focus distance stays sharp and the blur circle elsewhere grows as
 * f^2 / N |1/focus - 1/distance|, the thin lens's. A lens radius of 0 is the pinhole.
 *
 * Vignette: the image's brightness falls toward its corners as cos^4 of the angle off the
 * axis (the natural falloff of a thin lens: the cos^3 of the oblique pupil and distance, and the
 * cos of the sensor's tilt to the ray); a strength s blends it in: weight 1 - s + s cos^4.
 * For a panorama the angle is the elevation (the camera turns about its up axis). */
#ifndef SYLVA_LENS_H
#define SYLVA_LENS_H

#include "render/camera.h"

/* The ray from the lens point for (u1, u2) in [0, 1)^2 through the focus of the pinhole ray of
 * unit direction d: the origin into *o, the unit direction into *d. */
void lens_ray(const camera *c, float u1, float u2, vec3 *o, vec3 *d);
/* The vignette's weight for the pinhole ray of unit direction d, in (0, 1]. */
float lens_vignette(const camera *c, vec3 d);

#endif
