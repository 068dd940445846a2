/* accel_frame.h — the frame the Embree scene is built and traced in (accel.h). Single-precision
 * coordinates resolve half a millimetre 7 km from the scene's origin, and Embree moves every
 * ray into an instance's space by that instance's full transform, so at such a distance a
 * tuft of grass shifts by up to a millimetre against the camera's rays and a shadow ray's start
 * is lifted 7 mm off its blade (integrator_rays.h): finer than a pixel, but enough for a blade a
 * few millimetres wide to be missed or hit. The verification render, which the POV-Ray
 * cross-check compares with POV-Ray's double-precision trace, is therefore built in a frame
 * whose origin stands near the camera (accel_frame_near): every vertex, instance transform and
 * ray in Embree is the world's less that origin, and accel_shade's points are in the frame too.
 * What is looked up at a world position (the ground's colours) takes the point back with
 * accel_frame_world. The path tracer and the visibility maps keep the world's origin (a zero
 * frame: every function here is then the identity).
 *
 * The origin is a multiple of FRAME_STEP metres on each horizontal axis, so moving a float
 * coordinate into the frame is exact wherever the frame's coordinate is no larger than the
 * world's, and a camera within FRAME_STEP / 2 of the scene's origin keeps the world's frame. */
#ifndef SYLVA_ACCEL_FRAME_H
#define SYLVA_ACCEL_FRAME_H

#include "render/accel_types.h"

#define ACCEL_FRAME_STEP 1024.0 /* metres */

/* The frame's origin for a camera at eye: eye's x and y rounded to multiples of
 * ACCEL_FRAME_STEP, height 0 (heights stay as they are: the sky and the air read them). */
void accel_frame_near(const double eye[3], double frame[3]);

/* 1 when a's frame is not the world's. */
int accel_framed(const accel *a);

/* Transform xf (to the world) as a transform to a's frame. */
xform3x4 accel_frame_xf(const accel *a, const xform3x4 *xf);

/* World point p (3 floats) moved into a's frame, in place. */
void accel_frame_point(const accel *a, float p[3]);

/* Frame point p as a world point. */
vec3 accel_frame_world(const accel *a, vec3 p);

/* A copy of world mesh m in a's frame (positions moved, everything else as it is), owned by the
 * caller (mesh_free). NULL with err set when out of memory. */
mesh *accel_frame_mesh(const accel *a, const mesh *m, err_buf *err);

/* m's positions moved into a's frame, in place (a mesh the accel built and owns). */
void accel_frame_mesh_in_place(const accel *a, mesh *m);

#endif
