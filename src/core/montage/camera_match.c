/* camera_match.c — the camera solved from control points by GSL's trust-region
 * Levenberg-Marquardt with a central-difference Jacobian of fixed steps (camera_match.h). The unknowns are the
 * free parameters in their own units (metres, degrees, pixels); GSL's Marquardt scaling makes the
 * steps independent of those units. The checks that the points can fix the camera come first
 * (count, spread in the image and in space); the Jacobian's conditioning is checked at the
 * solution, where it decides the covariance. */
#include "montage/camera_match.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <gsl/gsl_sort_vector.h>

#define MAX_ITERATIONS 500
/* A point behind the camera during the iterations counts this many pixels off in u and v. */
#define BEHIND_PENALTY_PX 1e6
/* Spread below these fractions is "on one line": of the image's larger side (image), of the
 * points' largest spread (space). */
#define MIN_IMAGE_SPREAD 0.005
#define MIN_SPACE_SPREAD 0.01
/* The smallest singular value of the column-scaled Jacobian relative to the largest below which
 * the points cannot tell some parameters apart. */
#define MIN_CONDITION 1e-6

static const char *const param_names[CAMERA_PARAM_COUNT] = {
    "x", "y", "z", "heading", "pitch", "roll", "focal length", "k1", "k2"};

const char *camera_param_name(camera_param p)
{
    return (unsigned)p < CAMERA_PARAM_COUNT ? param_names[p] : "?";
}

typedef struct problem {
    camera_model start;
    unsigned free;
    int at[CAMERA_PARAM_COUNT]; /* index into the unknowns, -1 when fixed */
    uint32_t p;                 /* number of unknowns */
    const control_point *points;
    uint32_t n;
    double origin[3];
    gsl_vector *x_step, *f_plus, *f_minus; /* the Jacobian's scratch, owned by the solve */
} problem;

static void values_of(const camera_model *m, double v[CAMERA_PARAM_COUNT])
{
    v[CAMERA_X] = m->position[0], v[CAMERA_Y] = m->position[1], v[CAMERA_Z] = m->position[2];
    v[CAMERA_HEADING] = m->heading_deg, v[CAMERA_PITCH] = m->pitch_deg, v[CAMERA_ROLL] = m->roll_deg;
    v[CAMERA_FOCAL] = camera_model_focal_px(m);
    v[CAMERA_K1] = m->k1, v[CAMERA_K2] = m->k2;
}

static void model_of(const problem *P, const double v[CAMERA_PARAM_COUNT], camera_model *m)
{
    *m = P->start;
    m->position[0] = v[CAMERA_X], m->position[1] = v[CAMERA_Y], m->position[2] = v[CAMERA_Z];
    m->heading_deg = v[CAMERA_HEADING], m->pitch_deg = v[CAMERA_PITCH], m->roll_deg = v[CAMERA_ROLL];
    camera_model_set_focal_px(m, v[CAMERA_FOCAL]);
    m->k1 = v[CAMERA_K1], m->k2 = v[CAMERA_K2];
}

/* The camera for the unknowns x: the start with the free parameters replaced. */
static void model_at(const problem *P, const gsl_vector *x, camera_model *m)
{
    double v[CAMERA_PARAM_COUNT];
    values_of(&P->start, v);
    for (int k = 0; k < CAMERA_PARAM_COUNT; k++)
        if (P->at[k] >= 0) v[k] = gsl_vector_get(x, (size_t)P->at[k]);
    model_of(P, v, m);
}

static void local_of(const problem *P, const control_point *c, double out[3])
{
    for (int k = 0; k < 3; k++) out[k] = c->world[k] - P->origin[k];
}

/* f = projected minus given pixel, u and v of each point in turn. */
static int residuals(const gsl_vector *x, void *data, gsl_vector *f)
{
    const problem *P = data;
    camera_model m;
    model_at(P, x, &m);
    for (uint32_t i = 0; i < P->n; i++) {
        double w[3], px[2];
        local_of(P, &P->points[i], w);
        if (camera_project(&m, w, px)) px[0] = px[1] = BEHIND_PENALTY_PX;
        else px[0] -= P->points[i].pixel[0], px[1] -= P->points[i].pixel[1];
        gsl_vector_set(f, 2 * i, px[0]);
        gsl_vector_set(f, 2 * i + 1, px[1]);
    }
    return GSL_SUCCESS;
}

/* The Jacobian by central differences, each parameter stepped by an amount that moves the
 * pixels by about 1e-2 px (a millimetre, 1e-4 degree, 1e-5 of the focal length, 1e-4 in k1
 * and k2): GSL's own steps scale with the value, which for k1 = 0 or a position near the origin
 * is too small to see past the rounding of the pixels, and rank deficiency would hide. */
static int jacobian(const gsl_vector *x, void *data, gsl_matrix *J)
{
    problem *P = data;
    static const double steps[CAMERA_PARAM_COUNT] = {1e-3, 1e-3, 1e-3, 1e-4, 1e-4, 1e-4, 1e-5, 1e-4, 1e-4};
    for (int k = 0; k < CAMERA_PARAM_COUNT; k++) {
        if (P->at[k] < 0) continue;
        size_t j = (size_t)P->at[k];
        double v = gsl_vector_get(x, j), h = k == CAMERA_FOCAL ? steps[k] * fabs(v) : steps[k];
        gsl_vector_memcpy(P->x_step, x);
        gsl_vector_set(P->x_step, j, v + h);
        residuals(P->x_step, P, P->f_plus);
        gsl_vector_set(P->x_step, j, v - h);
        residuals(P->x_step, P, P->f_minus);
        for (size_t i = 0; i < J->size1; i++)
            gsl_matrix_set(J, i, j, (gsl_vector_get(P->f_plus, i) - gsl_vector_get(P->f_minus, i)) / (2.0 * h));
    }
    return GSL_SUCCESS;
}

/* Eigenvalues (ascending) of the symmetric dim x dim covariance of the rows of pts. */
static int spread(const double *pts, uint32_t n, size_t dim, double eig[3])
{
    double mean[3] = {0, 0, 0}, cov[9] = {0};
    for (uint32_t i = 0; i < n; i++)
        for (size_t a = 0; a < dim; a++) mean[a] += pts[i * dim + a] / n;
    for (uint32_t i = 0; i < n; i++)
        for (size_t a = 0; a < dim; a++)
            for (size_t b = 0; b < dim; b++)
                cov[a * dim + b] += (pts[i * dim + a] - mean[a]) * (pts[i * dim + b] - mean[b]) / n;
    gsl_matrix_view C = gsl_matrix_view_array(cov, dim, dim);
    gsl_vector_view E = gsl_vector_view_array(eig, dim);
    gsl_eigen_symm_workspace *ws = gsl_eigen_symm_alloc(dim);
    if (!ws) return -1;
    int rc = gsl_eigen_symm(&C.matrix, &E.vector, ws);
    gsl_eigen_symm_free(ws);
    gsl_sort_vector(&E.vector);
    for (size_t a = 0; a < dim; a++) eig[a] = fmax(eig[a], 0.0);
    return rc ? -1 : 0;
}

/* Refuses points that lie nearly on one line in the image or in space. */
static int check_spread(const problem *P, err_buf *err)
{
    double *pts = malloc((size_t)P->n * 3 * sizeof *pts); /* owned here */
    if (!pts) return err_nomem(err, "out of memory checking %u control points", P->n);
    double eig[3];
    for (uint32_t i = 0; i < P->n; i++) pts[2 * i] = P->points[i].pixel[0], pts[2 * i + 1] = P->points[i].pixel[1];
    int rc = spread(pts, P->n, 2, eig);
    double side = fmax(P->start.width, P->start.height), off_line = sqrt(eig[0]);
    if (!rc && off_line < MIN_IMAGE_SPREAD * side) {
        free(pts);
        return err_fail(err, ERR_INPUT,
                        "the %u control points lie nearly on one line in the image (%.3g px RMS from it; "
                        "the camera needs points at least %.3g px RMS away from any line, %.1f%% of the "
                        "image): add points above and below that line",
                        P->n, off_line, MIN_IMAGE_SPREAD * side, 100 * MIN_IMAGE_SPREAD);
    }
    for (uint32_t i = 0; i < P->n; i++) local_of(P, &P->points[i], pts + 3 * i);
    if (!rc) rc = spread(pts, P->n, 3, eig);
    free(pts);
    if (rc) return err_fail(err, ERR_INTERNAL, "the spread of the control points could not be computed");
    if (sqrt(eig[1]) < MIN_SPACE_SPREAD * sqrt(eig[2]))
        return err_fail(err, ERR_INPUT,
                        "the %u control points lie nearly on one line in space (%.3g m RMS from it, "
                        "along a spread of %.3g m): add points away from that line",
                        P->n, sqrt(eig[1]), sqrt(eig[2]));
    return 0;
}

/* Refuses a Jacobian whose columns (scaled to unit length) are nearly dependent, naming the
 * parameters the points cannot tell apart. */
static int check_rank(const problem *P, const gsl_matrix *J, err_buf *err)
{
    size_t rows = J->size1, p = J->size2;
    gsl_matrix *A = gsl_matrix_alloc(rows, p), *V = gsl_matrix_alloc(p, p); /* owned here */
    gsl_vector *S = gsl_vector_alloc(p), *work = gsl_vector_alloc(p);
    int rc = -1;
    if (!A || !V || !S || !work) {
        err_nomem(err, "out of memory checking the camera match");
        goto done;
    }
    gsl_matrix_memcpy(A, J);
    for (size_t j = 0; j < p; j++) {
        gsl_vector_view col = gsl_matrix_column(A, j);
        double norm = gsl_blas_dnrm2(&col.vector);
        if (!(norm > 0.0)) {
            for (int k = 0; k < CAMERA_PARAM_COUNT; k++)
                if (P->at[k] == (int)j)
                    err_fail(err, ERR_INPUT,
                             "the control points do not depend on the camera's %s at all: fix it "
                             "(give its value) instead of fitting it",
                             param_names[k]);
            goto done;
        }
        gsl_vector_scale(&col.vector, 1.0 / norm);
    }
    if (gsl_linalg_SV_decomp(A, V, S, work)) {
        err_fail(err, ERR_INTERNAL, "the camera match's Jacobian could not be decomposed");
        goto done;
    }
    double smax = gsl_vector_get(S, 0), smin = gsl_vector_get(S, p - 1);
    if (!(smin > MIN_CONDITION * smax)) {
        char names[256] = "";
        size_t used = 0;
        /* the parameters that take part in any direction the points do not see */
        for (int k = 0; k < CAMERA_PARAM_COUNT; k++) {
            int blind = 0;
            for (size_t c = 0; c < p && P->at[k] >= 0; c++)
                blind |= !(gsl_vector_get(S, c) > MIN_CONDITION * smax) &&
                         fabs(gsl_matrix_get(V, (size_t)P->at[k], c)) > 0.2;
            if (blind)
                used += (size_t)snprintf(names + used, used < sizeof names ? sizeof names - used : 0, "%s%s",
                                         used ? ", " : "", param_names[k]);
        }
        err_fail(err, ERR_INPUT,
                 "the control points cannot tell the camera's %s apart (the fit is rank deficient: "
                 "condition %.3g): fix one of them, or add points that separate them (at other "
                 "distances and across the whole image)",
                 names, smin / smax);
        goto done;
    }
    rc = 0;
done:
    gsl_matrix_free(A);
    gsl_matrix_free(V);
    gsl_vector_free(S);
    gsl_vector_free(work);
    return rc;
}

static double wrap180(double a)
{
    a = fmod(a, 360.0);
    if (a > 180.0) a -= 360.0;
    if (a <= -180.0) a += 360.0;
    return a;
}

/* The same view with pitch in [-90, 90], heading in [0, 360) and roll in (-180, 180]. */
static void normalise_angles(double v[CAMERA_PARAM_COUNT])
{
    double pitch = wrap180(v[CAMERA_PITCH]);
    if (fabs(pitch) > 90.0) {
        pitch = (pitch > 0 ? 180.0 : -180.0) - pitch;
        v[CAMERA_HEADING] += 180.0, v[CAMERA_ROLL] += 180.0;
    }
    v[CAMERA_PITCH] = pitch;
    v[CAMERA_HEADING] = fmod(v[CAMERA_HEADING], 360.0);
    if (v[CAMERA_HEADING] < 0.0) v[CAMERA_HEADING] += 360.0;
    v[CAMERA_ROLL] = wrap180(v[CAMERA_ROLL]);
}

static int check_start(const camera_model *s, unsigned free, uint32_t n, uint32_t p, err_buf *err)
{
    if (!s->width || !s->height)
        return err_fail(err, ERR_INPUT, "the photograph's size is %ux%u pixels; the camera match needs its width and height",
                        s->width, s->height);
    if (!(s->fov_deg > 0.0 && s->fov_deg < 180.0))
        return err_fail(err, ERR_INPUT, "the starting field of view is %g degrees; it must be in (0, 180)", s->fov_deg);
    double v[9] = {s->position[0], s->position[1], s->position[2], s->heading_deg, s->pitch_deg, s->roll_deg,
                   s->fov_deg, s->k1, s->k2};
    for (int k = 0; k < 9; k++)
        if (!isfinite(v[k]))
            return err_fail(err, ERR_INPUT, "the starting camera's %s is not a finite number", param_names[k]);
    if (free & ~((1u << CAMERA_PARAM_COUNT) - 1u))
        return err_fail(err, ERR_INTERNAL, "unknown camera parameters to fit (0x%x)", free);
    if (!p) return err_fail(err, ERR_INPUT, "no camera parameter is free: nothing to fit");
    if (n < p)
        return err_fail(err, ERR_INPUT,
                        "%u control point%s for %u free camera parameters: at least %u are needed (two "
                        "equations each, twice as many as unknowns, so that the residuals check the "
                        "fit); add points or fix parameters",
                        n, n == 1 ? "" : "s", p, p);
    return 0;
}

static int check_points(const problem *P, err_buf *err)
{
    for (uint32_t i = 0; i < P->n; i++) {
        const control_point *c = &P->points[i];
        double w[3];
        local_of(P, c, w);
        if (!isfinite(w[0]) || !isfinite(w[1]) || !isfinite(w[2]) || !isfinite(c->pixel[0]) || !isfinite(c->pixel[1]))
            return err_fail(err, ERR_INPUT, "control point %s (line %u) is not finite", c->id ? c->id : "?", c->line);
    }
    return 0;
}

/* The solution's residuals, RMSE, and the behind-the-camera check. */
static int fill_residuals(const problem *P, camera_match *M, err_buf *err)
{
    double sum = 0.0;
    for (uint32_t i = 0; i < P->n; i++) {
        double w[3], px[2];
        local_of(P, &P->points[i], w);
        if (camera_project(&M->camera, w, px))
            return err_fail(err, ERR_INPUT,
                            "control point %s (line %u) is behind the solved camera: the points do not "
                            "fit one view; check it, or start from a camera closer to the photograph's",
                            P->points[i].id ? P->points[i].id : "?", P->points[i].line);
        M->residual[i][0] = px[0] - P->points[i].pixel[0];
        M->residual[i][1] = px[1] - P->points[i].pixel[1];
        sum += M->residual[i][0] * M->residual[i][0] + M->residual[i][1] * M->residual[i][1];
    }
    M->rmse_px = sqrt(sum / P->n);
    M->sigma0_px = sqrt(sum / (2.0 * P->n - P->p));
    return 0;
}

camera_match *camera_match_solve(const camera_model *start, unsigned free, const control_point *points,
                                 uint32_t n, const double origin[3], err_buf *err)
{
    problem P = {.start = *start, .free = free, .points = points, .n = n};
    for (int k = 0; k < CAMERA_PARAM_COUNT; k++) P.at[k] = (free & CAMERA_FREE(k)) ? (int)P.p++ : -1;
    if (origin) memcpy(P.origin, origin, sizeof P.origin);
    if (check_start(start, free, n, P.p, err) || check_points(&P, err) || check_spread(&P, err)) return NULL;

    camera_match *M = calloc(1, sizeof *M); /* the caller's, through camera_match_free */
    if (!M || !(M->residual = calloc(n, sizeof *M->residual))) {
        camera_match_free(M);
        err_nomem(err, "out of memory matching the camera");
        return NULL;
    }
    /* GSL's default error handler aborts; its failures are reported here instead (restored on
     * return; the solve runs on one thread) */
    gsl_error_handler_t *handler = gsl_set_error_handler_off();
    gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
    params.trs = gsl_multifit_nlinear_trs_lm;
    gsl_multifit_nlinear_fdf fdf = {.f = residuals, .df = jacobian, .fvv = NULL, .n = 2 * (size_t)n, .p = P.p, .params = &P};
    gsl_multifit_nlinear_workspace *w = gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, fdf.n, P.p);
    gsl_vector *x0 = gsl_vector_alloc(P.p);
    gsl_matrix *covar = gsl_matrix_alloc(P.p, P.p);
    P.x_step = gsl_vector_alloc(P.p), P.f_plus = gsl_vector_alloc(fdf.n), P.f_minus = gsl_vector_alloc(fdf.n);
    int ok = 0;
    if (!w || !x0 || !covar || !P.x_step || !P.f_plus || !P.f_minus) {
        err_nomem(err, "out of memory matching the camera");
        goto done;
    }
    double v[CAMERA_PARAM_COUNT];
    values_of(start, v);
    for (int k = 0; k < CAMERA_PARAM_COUNT; k++)
        if (P.at[k] >= 0) gsl_vector_set(x0, (size_t)P.at[k], v[k]);
    int info = 0;
    int status = gsl_multifit_nlinear_init(x0, &fdf, w);
    if (!status) status = gsl_multifit_nlinear_driver(MAX_ITERATIONS, 1e-12, 1e-12, 0.0, NULL, NULL, &info, w);
    M->iterations = (uint32_t)gsl_multifit_nlinear_niter(w);
    if (status && status != GSL_ENOPROG) {
        err_fail(err, ERR_INPUT,
                 "the camera match did not converge in %u iterations (%s): start from a camera closer "
                 "to the photograph's (its position, and the heading of the view within a few degrees)",
                 M->iterations, gsl_strerror(status));
        goto done;
    }
    const gsl_vector *x = gsl_multifit_nlinear_position(w);
    for (int k = 0; k < CAMERA_PARAM_COUNT; k++)
        if (P.at[k] >= 0) v[k] = gsl_vector_get(x, (size_t)P.at[k]);
    if (!(v[CAMERA_FOCAL] > 0.0)) {
        err_fail(err, ERR_INPUT, "the camera match gave a focal length of %g pixels: the points do not fit one "
                 "view; check them, or fix the focal length", v[CAMERA_FOCAL]);
        goto done;
    }
    normalise_angles(v);
    memcpy(M->value, v, sizeof v);
    model_of(&P, v, &M->camera);
    M->free = free, M->n_points = n;
    if (fill_residuals(&P, M, err)) goto done;
    const gsl_matrix *J = gsl_multifit_nlinear_jac(w);
    if (check_rank(&P, J, err)) goto done;
    if (gsl_multifit_nlinear_covar(J, 0.0, covar)) {
        err_fail(err, ERR_INTERNAL, "the covariance of the camera match could not be computed");
        goto done;
    }
    for (int k = 0; k < CAMERA_PARAM_COUNT; k++)
        if (P.at[k] >= 0) M->sigma[k] = M->sigma0_px * sqrt(gsl_matrix_get(covar, (size_t)P.at[k], (size_t)P.at[k]));
    ok = 1;
done:
    gsl_vector_free(x0);
    gsl_vector_free(P.x_step);
    gsl_vector_free(P.f_plus);
    gsl_vector_free(P.f_minus);
    gsl_matrix_free(covar);
    if (w) gsl_multifit_nlinear_free(w);
    gsl_set_error_handler(handler);
    if (ok) return M;
    camera_match_free(M);
    return NULL;
}

void camera_match_aim(camera_model *start, const control_point *points, uint32_t n, const double origin[3])
{
    double f = camera_model_focal_px(start), east = 0.0, north = 0.0, pitch = 0.0, weight = 0.0;
    for (uint32_t i = 0; i < n; i++) {
        double d[3];
        for (int k = 0; k < 3; k++) d[k] = points[i].world[k] - (origin ? origin[k] : 0.0) - start->position[k];
        double level = hypot(d[0], d[1]);
        if (!(level > 0.0) || !isfinite(level)) continue;
        double heading = atan2(d[0], d[1]) - atan((points[i].pixel[0] - 0.5 * start->width) / f);
        east += level * sin(heading), north += level * cos(heading);
        pitch += level * (atan2(d[2], level) - atan((0.5 * start->height - points[i].pixel[1]) / f));
        weight += level;
    }
    if (!(weight > 0.0)) return;
    double heading_deg = atan2(east, north) * 180.0 / M_PI;
    start->heading_deg = heading_deg < 0.0 ? heading_deg + 360.0 : heading_deg;
    start->pitch_deg = pitch / weight * 180.0 / M_PI;
    start->roll_deg = 0.0;
}

void camera_match_free(camera_match *m)
{
    if (!m) return;
    free(m->residual);
    free(m);
}
