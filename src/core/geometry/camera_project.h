/* camera_project.h — the camera as a photograph sees it, in double precision: a pinhole aimed by
 * heading, pitch and roll exactly as the scene file aims it (geometry/camera_frame.h), a horizontal
 * field of view, an image size, and radial lens distortion k1, k2. A world point (local metres)
 * projects to a continuous pixel (x right, y down, (0, 0) the top-left corner of the image, as
 * render/camera.c has it); a pixel unprojects to a unit ray. With k1 = k2 = 0 the two are the
 * renderer's camera_direction and its inverse. Nothing is allocated.
 *
 * Distortion acts on the tangent-plane coordinates of the ray, x = (d . right) / (d . forward) and
 * y = (d . up) / (d . forward): x_d = x (1 + k1 r^2 + k2 r^4), y_d likewise, r^2 = x^2 + y^2 (the
 * radial terms of Brown's model, as OpenCV and ImGRAFT write them). The pixel is then
 * (W/2 + f x_d, H/2 - f y_d), f = W / (2 tan(fov/2)) the focal length in pixels (square pixels,
 * principal point at the image centre). */
#ifndef SYLVA_CAMERA_PROJECT_H
#define SYLVA_CAMERA_PROJECT_H

#include <stdint.h>

#include "scene/scene_settings.h"

typedef struct camera_model {
    double position[3];   /* the eye, local metres */
    double heading_deg;   /* compass bearing of the view, clockwise from north (+Y) */
    double pitch_deg;     /* angle of the view above the horizon, in [-90, 90] */
    double roll_deg;      /* turn about the view, clockwise seen from behind (camera_frame.h) */
    double fov_deg;       /* horizontal field of view, in (0, 180) */
    uint32_t width, height; /* image size in pixels */
    double k1, k2;        /* radial distortion on the tangent plane; 0, 0: a perfect pinhole */
} camera_model;

/* The focal length in pixels, W / (2 tan(fov / 2)). */
double camera_model_focal_px(const camera_model *m);
/* Sets fov_deg from a focal length in pixels. */
void camera_model_set_focal_px(camera_model *m, double focal_px);
/* Sets fov_deg from a lens focal length and the sensor's width (millimetres, the image's width):
 * fov = 2 atan(sensor_width / (2 focal_length)). */
void camera_model_set_focal_mm(camera_model *m, double focal_mm, double sensor_width_mm);
/* The lens focal length in millimetres on a sensor sensor_width_mm wide. */
double camera_model_focal_mm(const camera_model *m, double sensor_width_mm);

/* Unit forward, right and up vectors: camera_frame's for a camera aimed by m's heading, pitch and
 * roll. */
void camera_model_frame(const camera_model *m, double forward[3], double right[3], double up[3]);

/* The scene camera that renders m's view (position, direction, up, roll, fov; no look_at, no
 * focal length, no height above ground); its distortion is not part of camera_settings. */
void camera_model_to_settings(const camera_model *m, camera_settings *s);
/* m's position, heading, pitch, roll and fov from a loaded scene camera (any way of aiming it),
 * with the given image size and no distortion. A view straight up or down takes its heading from
 * the top of the image. */
void camera_model_from_settings(camera_model *m, const camera_settings *s, uint32_t width, uint32_t height);

/* The continuous pixel where world point p appears. Returns 0, or -1 when p is not in front of
 * the camera (on or behind the plane of the eye). A pixel outside the image is still returned. */
int camera_project(const camera_model *m, const double p[3], double pixel[2]);

/* The unit ray from the eye through continuous pixel (x, y), undoing the distortion by Newton
 * steps on the radius. Returns 0, or -1 when no ray maps to that pixel (strong distortion folds
 * the image: the radius is beyond where x (1 + k1 r^2 + k2 r^4) stops growing). */
int camera_unproject(const camera_model *m, double x, double y, double ray[3]);

#endif
