/* curved_ray.h — camera rays over a curved Earth with atmospheric refraction, traced in the flat
 * scene frame (docs/models/curvature.md).
 *
 * The scene stays flat (the terrain, objects and plant instances are not moved); instead a
 * camera ray leaving the camera along unit d follows the path
 *     P(t) = o + t d + (0, 0, a t^2),   a = (1 - k) / (2 R) (dx^2 + dy^2),
 * so that at horizontal distance s = t |d_xy| it stands (1 - k) s^2 / (2 R) above the straight
 * ray: what stands there appears that much lower. The path is traced as a chain of straight
 * chords. The first runs from the camera to t1 = tol / |a|, the next ones from t_i to
 * t_i + 2 sqrt(t_i t1); a chord of length L lies at most |a| L^2 / 4 from the parabola, so seen
 * from the camera no chord strays from the path by more than the angle tol, which is set to a
 * twentieth of the smallest pixel of the image. The chain ends where the path leaves the
 * scene's bounding box for good. A ray for which a is 0 (straight up or down) or the curvature
 * is off is one straight ray, as on a flat Earth.
 *
 * Nothing here allocates; a curved_rays is read-only once set up, shared by all threads.
 */
#ifndef SYLVA_CURVED_RAY_H
#define SYLVA_CURVED_RAY_H

#include <stdint.h>

#include "render/camera.h"
#include "scene/scene_settings.h"
#include "util/vec3.h"

typedef struct curved_rays {
    int on;                  /* 0: every camera ray is straight */
    double lift;             /* (1 - k) / (2 R), 1/m */
    double tolerance;        /* radians, as seen from the camera */
    double origin[3];        /* the camera's eye */
    double lo[3], hi[3];     /* the scene's bounds, slightly enlarged */
} curved_rays;

/* The share of the smallest pixel's angle that a chord may stray from the path. */
#define CURVED_RAY_PIXEL_SHARE 0.05
/* The most chords one camera ray is split into; the last one reaches the end of the path. */
#define CURVED_RAY_MAX_CHORDS 65536u

/* Sets cr up for camera c over a scene within [lo, hi]; earth NULL or its curvature off gives
 * straight rays. */
void curved_rays_init(curved_rays *cr, const earth_settings *earth, const camera *c, const float lo[3],
                      const float hi[3]);

/* One camera ray's chain of chords, walked with curved_path_next. */
typedef struct curved_path {
    double d[3];             /* unit direction at the camera */
    double a;                /* lift per t^2 along this ray */
    double t, t_first, t_end;
    uint32_t chords;         /* handed out so far */
    int straight;            /* 1: one straight ray of infinite length */
    const curved_rays *cr;
} curved_path;

void curved_path_begin(curved_path *p, const curved_rays *cr, vec3 d);

/* The next chord into *org, *dir (unit) and *len (metres), with the path parameter at its start
 * *t0 and its span *dt: a hit at distance u along the chord lies at path parameter
 * t0 + u / len * dt. A straight ray is one chord of *len INFINITY, *t0 0 and *dt 0, whose hit at
 * u lies at u. Returns 1, or 0 when the path has left the scene. */
int curved_path_next(curved_path *p, vec3 *org, vec3 *dir, float *len, double *t0, double *dt);

#endif
