/* test_camera_match.c — the camera solved from control points (montage/camera_match.h):
 * exact points give back the camera (position within 0.5 m, angles within 0.05 degrees, focal
 * length within 0.5 %), with distortion too; with 1 px of noise the reported uncertainties cover
 * the truth as often as a 1-sigma and a 2-sigma interval should; degenerate point sets are refused
 * with the sentence that says why; and the real Engabreen survey (ImGRAFT's photograph and 28
 * points, camera position fixed) fits with an RMSE below ImGRAFT's 5.1 px (skipped without the
 * shared data set). */
#include <sys/stat.h>

#include "harness.h"
#include "montage/camera_match.h"
#include "util/rng.h"

#define ENGABREEN SYLVA_SHARED_DATA_DIR "/photos/imgraft-engabreen/gcp8902.txt"

static const camera_model truth = {.position = {120.0, -340.0, 215.0}, .heading_deg = 231.0, .pitch_deg = -4.0,
                                   .roll_deg = 1.2, .fov_deg = 40.3, .width = 4290, .height = 2856};

/* Eight pixels spread over the image and their distances (metres): near and far. */
static const double spots[8][3] = {
    {300, 400, 2600}, {2100, 300, 3900}, {3900, 500, 1800}, {500, 1500, 900},
    {3700, 1600, 450}, {900, 2600, 120}, {2300, 2000, 300}, {4000, 2700, 60},
};

/* n control points of camera c: the world points seen at spots[i] (wrapping) with distance
 * scaled by 1 + i / 8 for the second round; pixels exact. */
static void make_points(const camera_model *c, control_point *pts, uint32_t n)
{
    for (uint32_t i = 0; i < n; i++) {
        const double *s = spots[i % 8];
        double ray[3], scale = 1.0 + (double)(i / 8) * 0.37;
        double px = i < 8 ? s[0] : fmod(s[0] * 1.7 + 233.0 * i, c->width);
        double py = i < 8 ? s[1] : fmod(s[1] * 1.3 + 97.0 * i, c->height);
        CHECK_INT(camera_unproject(c, px, py, ray), 0);
        pts[i] = (control_point){.id = "p", .pixel = {px, py}, .line = i + 1};
        for (int k = 0; k < 3; k++) pts[i].world[k] = c->position[k] + s[2] * scale * ray[k];
    }
}

static camera_model perturbed(const camera_model *c)
{
    camera_model s = *c;
    s.position[0] += 25, s.position[1] -= 15, s.position[2] += 8;
    s.heading_deg += 6, s.pitch_deg -= 2, s.roll_deg += 1.5;
    camera_model_set_focal_px(&s, camera_model_focal_px(c) * 1.1);
    s.k1 = s.k2 = 0;
    return s;
}

static double angle_diff(double a, double b) { return fabs(remainder(a - b, 360.0)); }

static void check_recovered(const camera_match *m, const camera_model *c)
{
    for (int k = 0; k < 3; k++) CHECK_NEAR(m->camera.position[k], c->position[k], 0.5);
    CHECK(angle_diff(m->camera.heading_deg, c->heading_deg) <= 0.05);
    CHECK_NEAR(m->camera.pitch_deg, c->pitch_deg, 0.05);
    CHECK(angle_diff(m->camera.roll_deg, c->roll_deg) <= 0.05);
    CHECK_NEAR(camera_model_focal_px(&m->camera) / camera_model_focal_px(c), 1.0, 0.005);
}

TEST(round_trip_exact_points)
{
    control_point pts[8];
    make_points(&truth, pts, 8);
    camera_model start = perturbed(&truth);
    err_buf err = {{0}};
    unsigned free = CAMERA_FREE_POSITION | CAMERA_FREE_ANGLES | CAMERA_FREE(CAMERA_FOCAL);
    camera_match *m = camera_match_solve(&start, free, pts, 8, NULL, &err);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    CHECK(m != NULL);
    if (!m) return;
    check_recovered(m, &truth);
    CHECK(m->rmse_px < 1e-4);
    fprintf(stderr, "round trip: position off by %.2e %.2e %.2e m, heading %.2e pitch %.2e roll %.2e deg, "
                    "focal %.2e relative, RMSE %.2e px, %u iterations\n",
            m->camera.position[0] - truth.position[0], m->camera.position[1] - truth.position[1],
            m->camera.position[2] - truth.position[2], remainder(m->camera.heading_deg - truth.heading_deg, 360),
            m->camera.pitch_deg - truth.pitch_deg, m->camera.roll_deg - truth.roll_deg,
            camera_model_focal_px(&m->camera) / camera_model_focal_px(&truth) - 1, m->rmse_px, m->iterations);
    CHECK_INT(m->n_points, 8);
    CHECK_NEAR(m->value[CAMERA_HEADING], m->camera.heading_deg, 0);
    CHECK_NEAR(m->sigma[CAMERA_K1], 0, 0); /* fixed */
    camera_match_free(m);
}

TEST(round_trip_with_distortion_and_map_origin)
{
    camera_model c = truth;
    c.k1 = -0.12, c.k2 = 0.05;
    control_point pts[16];
    make_points(&c, pts, 16);
    /* the points in map coordinates; the solver takes local = map - origin */
    const double origin[3] = {446000.0, 7396000.0, 0.0};
    for (int i = 0; i < 16; i++)
        for (int k = 0; k < 3; k++) pts[i].world[k] += origin[k];
    camera_model start = perturbed(&c);
    err_buf err = {{0}};
    unsigned free = CAMERA_FREE_POSITION | CAMERA_FREE_ANGLES | CAMERA_FREE(CAMERA_FOCAL) |
                    CAMERA_FREE(CAMERA_K1) | CAMERA_FREE(CAMERA_K2);
    camera_match *m = camera_match_solve(&start, free, pts, 16, origin, &err);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    CHECK(m != NULL);
    if (!m) return;
    check_recovered(m, &c);
    CHECK_NEAR(m->camera.k1, c.k1, 1e-4);
    CHECK_NEAR(m->camera.k2, c.k2, 1e-3);
    CHECK(m->rmse_px < 1e-4);
    camera_match_free(m);
}

/* A standard normal number from r (Box-Muller). */
static double normal(sylva_rng *r)
{
    double u = rng_next_double(r), v = rng_next_double(r);
    return sqrt(-2.0 * log(1.0 - u)) * cos(2.0 * M_PI * v);
}

/* Over `draws` noise draws of `noise_px` (standard deviation, each of u and v), the fraction of
 * free parameters within 1 and 2 reported sigma of the truth. */
static void noise_coverage(double noise_px, int draws, double *within1, double *within2)
{
    enum { N = 10 };
    unsigned free = CAMERA_FREE_POSITION | CAMERA_FREE_ANGLES | CAMERA_FREE(CAMERA_FOCAL);
    const double want[CAMERA_PARAM_COUNT] = {truth.position[0], truth.position[1], truth.position[2],
                                             truth.heading_deg, truth.pitch_deg, truth.roll_deg,
                                             camera_model_focal_px(&truth), 0, 0};
    int in1 = 0, in2 = 0, checks = 0;
    for (int d = 0; d < draws; d++) {
        control_point pts[N];
        make_points(&truth, pts, N);
        sylva_rng r;
        rng_stream(&r, (uint64_t)(noise_px * 1000), "camera match noise", (uint64_t)d);
        for (int i = 0; i < N; i++)
            pts[i].pixel[0] += noise_px * normal(&r), pts[i].pixel[1] += noise_px * normal(&r);
        camera_model start = perturbed(&truth);
        err_buf err = {{0}};
        camera_match *m = camera_match_solve(&start, free, pts, N, NULL, &err);
        if (!m) fprintf(stderr, "%s\n", err.msg);
        CHECK(m != NULL);
        if (!m) continue;
        CHECK(m->rmse_px > 0.3 * noise_px && m->rmse_px < 2.5 * noise_px);
        for (int k = 0; k < CAMERA_PARAM_COUNT; k++) {
            if (!(free & CAMERA_FREE(k))) continue;
            double off = k == CAMERA_HEADING || k == CAMERA_ROLL ? angle_diff(m->value[k], want[k]) : fabs(m->value[k] - want[k]);
            CHECK(m->sigma[k] > 0);
            in1 += off <= m->sigma[k];
            in2 += off <= 2 * m->sigma[k];
            checks++;
        }
        if (d == 0)
            fprintf(stderr, "%g px noise, draw 0: 1-sigma x %.3f y %.3f z %.3f m, heading %.4f pitch %.4f roll %.4f deg, "
                            "focal %.2f px; RMSE %.2f px\n",
                    noise_px, m->sigma[CAMERA_X], m->sigma[CAMERA_Y], m->sigma[CAMERA_Z], m->sigma[CAMERA_HEADING],
                    m->sigma[CAMERA_PITCH], m->sigma[CAMERA_ROLL], m->sigma[CAMERA_FOCAL], m->rmse_px);
        camera_match_free(m);
    }
    fprintf(stderr, "%g px noise: truth within 1 sigma %d / %d, within 2 sigma %d / %d\n", noise_px, in1, checks, in2,
            checks);
    *within1 = (double)in1 / checks, *within2 = (double)in2 / checks;
}

TEST(noise_covered_by_reported_uncertainty)
{
    /* 1 sigma should hold 68 % of the time and 2 sigma 95 %: the reported uncertainty is neither
     * too small (truth outside) nor far too large; at 3 px the scaling by the residual variance
     * is what keeps it so. */
    static const double noise[] = {1.0, 3.0};
    for (int j = 0; j < 2; j++) {
        double in1, in2;
        noise_coverage(noise[j], 100, &in1, &in2);
        CHECK(in1 >= 0.55 && in1 <= 0.82);
        CHECK(in2 >= 0.88);
    }
}

TEST(aimed_at_the_points)
{
    /* no direction known: the start looks north, level; aimed at the points it is within a few
     * degrees of the truth, and the solve from there recovers the camera */
    control_point pts[8];
    make_points(&truth, pts, 8);
    camera_model start = perturbed(&truth);
    start.heading_deg = 0, start.pitch_deg = 0, start.roll_deg = 0;
    camera_match_aim(&start, pts, 8, NULL);
    CHECK(angle_diff(start.heading_deg, truth.heading_deg) < 5.0);
    CHECK_NEAR(start.pitch_deg, truth.pitch_deg, 5.0);
    CHECK_NEAR(start.roll_deg, 0, 0);
    camera_match *m = camera_match_solve(&start, CAMERA_FREE_POSITION | CAMERA_FREE_ANGLES | CAMERA_FREE(CAMERA_FOCAL),
                                         pts, 8, NULL, NULL);
    CHECK(m != NULL);
    if (m) check_recovered(m, &truth);
    camera_match_free(m);
}

/* The solve is refused with a message holding `what`. */
static void refused(const camera_model *start, unsigned free, const control_point *pts, uint32_t n, const char *what)
{
    err_buf err = {{0}};
    camera_match *m = camera_match_solve(start, free, pts, n, NULL, &err);
    CHECK(m == NULL);
    camera_match_free(m);
    CHECK_STR_CONTAINS(err.msg, what);
    CHECK_INT(err.status, ERR_INPUT);
}

TEST(degenerate_points_refused)
{
    control_point pts[12];
    make_points(&truth, pts, 12);
    camera_model start = perturbed(&truth);
    unsigned all7 = CAMERA_FREE_POSITION | CAMERA_FREE_ANGLES | CAMERA_FREE(CAMERA_FOCAL);
    refused(&start, all7, pts, 6, "6 control points for 7 free camera parameters: at least 7 are needed");
    refused(&start, 0, pts, 8, "no camera parameter is free");
    /* on one line in the image: points along a horizontal row of pixels, various distances */
    control_point row[9];
    for (int i = 0; i < 9; i++) {
        double ray[3];
        camera_unproject(&truth, 200.0 + 450.0 * i, 1400.0 + 0.3 * (i % 2), ray);
        row[i] = (control_point){.id = "r", .pixel = {200.0 + 450.0 * i, 1400.0 + 0.3 * (i % 2)}};
        for (int k = 0; k < 3; k++) row[i].world[k] = truth.position[k] + (100.0 + 300.0 * i) * ray[k];
    }
    refused(&start, all7, row, 9, "lie nearly on one line in the image");
    /* on one line in space, with pixels spread over the image (no camera sees them so) */
    control_point line[8];
    for (int i = 0; i < 8; i++) {
        line[i] = (control_point){.id = "l", .pixel = {spots[i][0], spots[i][1]}};
        line[i].world[0] = 10.0 * i, line[i].world[1] = 20.0 * i, line[i].world[2] = 3.0 * i;
    }
    refused(&start, all7, line, 8, "lie nearly on one line in space");
    /* rank deficient: every point at the same distance from the image centre, so focal length,
     * k1 and k2 all scale the radius alike */
    camera_model fixed = truth;
    control_point ring[10];
    for (int i = 0; i < 10; i++) {
        double a = 2 * M_PI * i / 10, px = 2145 + 1000 * cos(a), py = 1428 + 1000 * sin(a), ray[3];
        camera_unproject(&truth, px, py, ray);
        ring[i] = (control_point){.id = "c", .pixel = {px, py}};
        for (int k = 0; k < 3; k++) ring[i].world[k] = truth.position[k] + (200.0 + 150.0 * i) * ray[k];
    }
    fixed.heading_deg += 1;
    refused(&fixed, CAMERA_FREE_ANGLES | CAMERA_FREE(CAMERA_FOCAL) | CAMERA_FREE(CAMERA_K1) | CAMERA_FREE(CAMERA_K2),
            ring, 10, "cannot tell the camera's focal length, k1, k2 apart");
    /* a bad start */
    camera_model nowidth = start;
    nowidth.width = 0;
    refused(&nowidth, all7, pts, 8, "needs its width and height");
    camera_model nan_start = start;
    nan_start.roll_deg = NAN;
    refused(&nan_start, all7, pts, 8, "starting camera's roll is not a finite number");
}

/* The Engabreen survey (ImGRAFT's demo data): the camera fixed at its surveyed position, the
 * view, focal length and distortion k1 fitted. */
TEST(engabreen_survey)
{
    struct stat st;
    if (stat(ENGABREEN, &st) != 0) SKIP("the shared data set is not at %s", ENGABREEN);
    err_buf err = {{0}};
    control_points *cp = control_points_read(ENGABREEN, NULL, &err);
    CHECK(cp != NULL);
    if (!cp) return;
    const double origin[3] = {446700.0, 7396600.0, 700.0};
    camera_model start = {.position = {446722.0 - origin[0], 7396671.0 - origin[1], 770.0 - origin[2]},
                          .width = 4290, .height = 2856};
    camera_model_set_focal_mm(&start, 30.0, 22.0); /* EXIF focal length, Canon APS-C sensor */
    camera_match_aim(&start, cp->points, cp->n, origin); /* the photograph has no direction */
    CHECK(angle_diff(start.heading_deg, 230.8) < 2.0);
    /* k1 alone: k2 as well lowers the RMSE by 0.002 px and comes out at a quarter of its 1-sigma */
    unsigned free = CAMERA_FREE_ANGLES | CAMERA_FREE(CAMERA_FOCAL) | CAMERA_FREE(CAMERA_K1);
    camera_match *m = camera_match_solve(&start, free, cp->points, cp->n, origin, &err);
    if (!m) fprintf(stderr, "%s\n", err.msg);
    CHECK(m != NULL);
    if (m) {
        fprintf(stderr, "Engabreen: heading %.3f +- %.3f, pitch %.3f +- %.3f, roll %.3f +- %.3f deg, focal %.1f +- %.1f px "
                        "(%.2f mm), k1 %.4f +- %.4f, RMSE %.3f px, %u iterations\n",
                m->value[CAMERA_HEADING], m->sigma[CAMERA_HEADING], m->value[CAMERA_PITCH], m->sigma[CAMERA_PITCH],
                m->value[CAMERA_ROLL], m->sigma[CAMERA_ROLL], m->value[CAMERA_FOCAL], m->sigma[CAMERA_FOCAL],
                camera_model_focal_mm(&m->camera, 22.0), m->value[CAMERA_K1], m->sigma[CAMERA_K1], m->rmse_px,
                m->iterations);
        fprintf(stderr, "| point | u | v | du | dv |\n|---|---|---|---|---|\n");
        for (uint32_t i = 0; i < cp->n; i++)
            fprintf(stderr, "| %s | %.1f | %.1f | %.2f | %.2f |\n", cp->points[i].id, cp->points[i].pixel[0],
                    cp->points[i].pixel[1], m->residual[i][0], m->residual[i][1]);
        CHECK(m->rmse_px <= 5.1);
        CHECK_NEAR(camera_model_focal_mm(&m->camera, 22.0), 30.0, 3.0);
    }
    camera_match_free(m);
    control_points_free(cp);
}

TEST_LIST(TEST_CASE(round_trip_exact_points), TEST_CASE(round_trip_with_distortion_and_map_origin),
          TEST_CASE(noise_covered_by_reported_uncertainty), TEST_CASE(aimed_at_the_points), TEST_CASE(degenerate_points_refused),
          TEST_CASE(engabreen_survey))
