/* camera_match.h — the camera of a photograph solved from control points: the parameters of a
 * camera_model (position, heading, pitch, roll, focal length, distortion k1 and k2), each free or
 * fixed, fitted by nonlinear least squares (GSL's multifit_nlinear, Levenberg-Marquardt in a trust
 * region) so that the control points' world positions project onto their pixels. The caller gives
 * the start (the EXIF position and direction when the photograph has them, the fixed values).
 *
 * What it reports: each point's residual in pixels, the RMSE, and each free parameter's 1-sigma
 * uncertainty from the covariance (J^T J)^-1 scaled by the residual variance
 * chi^2 / (2 n - p). What it refuses, with a sentence saying what would do: fewer points than
 * free parameters (each point gives two equations; twice the unknowns are needed so that the
 * residuals can check the fit), points nearly on one line in the image or in space, parameters
 * the points cannot tell apart (a rank-deficient Jacobian at the solution), a point behind the
 * solved camera, and a solve that does not converge. docs/photomontage.md, "Camera match". */
#ifndef SYLVA_CAMERA_MATCH_H
#define SYLVA_CAMERA_MATCH_H

#include <stdint.h>

#include "geometry/camera_project.h"
#include "montage/control_points.h"
#include "util/err.h"

typedef enum camera_param {
    CAMERA_X, CAMERA_Y, CAMERA_Z,                  /* metres */
    CAMERA_HEADING, CAMERA_PITCH, CAMERA_ROLL,     /* degrees */
    CAMERA_FOCAL,                                  /* focal length in pixels */
    CAMERA_K1, CAMERA_K2,                          /* radial distortion */
    CAMERA_PARAM_COUNT
} camera_param;

#define CAMERA_FREE(p) (1u << (p))
#define CAMERA_FREE_POSITION (CAMERA_FREE(CAMERA_X) | CAMERA_FREE(CAMERA_Y) | CAMERA_FREE(CAMERA_Z))
#define CAMERA_FREE_ANGLES (CAMERA_FREE(CAMERA_HEADING) | CAMERA_FREE(CAMERA_PITCH) | CAMERA_FREE(CAMERA_ROLL))

/* The parameter's name as messages and tables give it ("x", "heading", "focal length", "k1"). */
const char *camera_param_name(camera_param p);

typedef struct camera_match {
    camera_model camera;             /* the solution; the fixed parameters are the start's */
    unsigned free;                   /* CAMERA_FREE bits of the fitted parameters */
    double value[CAMERA_PARAM_COUNT];/* the solution by parameter (focal length in pixels) */
    double sigma[CAMERA_PARAM_COUNT];/* 1-sigma uncertainty of each free parameter; 0 when fixed */
    uint32_t n_points;
    double (*residual)[2];           /* n_points (du, dv): projected minus given pixel; owned */
    double rmse_px;                  /* sqrt(mean(du^2 + dv^2)) over the points */
    double sigma0_px;                /* the residual standard error, sqrt(chi^2 / (2 n - p)) */
    uint32_t iterations;
} camera_match;

/* Solves the camera from n control points (world - origin is a point's local position; origin
 * NULL: world is local already), starting from `start` and fitting the parameters in `free`
 * (CAMERA_FREE bits). Returns a new match (caller frees with camera_match_free) or NULL with err
 * set to why the points cannot fix the camera. */
camera_match *camera_match_solve(const camera_model *start, unsigned free, const control_point *points,
                                 uint32_t n, const double origin[3], err_buf *err);
void camera_match_free(camera_match *m); /* accepts NULL */

/* Aims start at the control points when no direction is known: from its position and focal
 * length, each point's bearing and elevation less the angle its pixel lies off the image centre
 * gives a heading and a pitch; start takes their means weighted by the points' distances (far
 * points are the least sensitive to an error in the position; circular for the heading) and
 * roll 0. A point at the camera's position is skipped. */
void camera_match_aim(camera_model *start, const control_point *points, uint32_t n, const double origin[3]);

#endif
