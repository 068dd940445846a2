/* camera.h — the pinhole camera: position, orthonormal frame from the view direction and the
 * up vector, horizontal field of view (from focal length and sensor width when given). Pixel
 * (0, 0) is the top-left corner of the image. */
#ifndef SYLVA_CAMERA_H
#define SYLVA_CAMERA_H

#include <stdint.h>

#include "scene/scene_file.h"
#include "util/vec3.h"

typedef struct camera {
    vec3 origin;
    vec3 forward, right, up; /* unit; right = forward x up */
    float tan_half_x, tan_half_y;
    uint32_t width, height;
} camera;

void camera_init(camera *c, const camera_settings *s, uint32_t width, uint32_t height);
/* Unit direction through image position (x, y) in pixels (continuous). */
vec3 camera_direction(const camera *c, float x, float y);

#endif
