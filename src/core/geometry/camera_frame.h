/* camera_frame.h — the camera's orthonormal frame as every back end aims it: forward from
 * look_at (or direction), right = forward x up, the image's up = right x forward, then right and
 * up turned by the roll about forward — clockwise as seen from behind the camera, so a positive
 * roll lowers the image's right side and the scene appears turned the other way. The path
 * tracer builds its rays from this frame and the POV-Ray export writes its up as `sky`, so both
 * show the same view. Computed in double precision from the scene's numbers; nothing allocated.
 */
#ifndef SYLVA_CAMERA_FRAME_H
#define SYLVA_CAMERA_FRAME_H

#include "scene/scene_settings.h"

/* Unit forward, right and up vectors of s's camera (the loader has refused a view parallel to
 * up or of zero length). */
void camera_frame(const camera_settings *s, double forward[3], double right[3], double up[3]);

/* The radius in metres of the thin lens's pupil, focal length / (2 f-number), 0 for a pinhole
 * (f_number 0). The focal length is the one given, else the one the field of view implies on
 * the sensor width: w / (2 tan(fov / 2)), for a panorama w / fov (render/lens.h; the POV-Ray
 * export's focal blur). */
double camera_lens_radius(const camera_settings *s);

#endif
