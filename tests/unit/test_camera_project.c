/* test_camera_project.c — the double-precision camera of the camera match
 * (geometry/camera_project.h): without distortion it is the renderer's camera (a point along
 * camera_direction(x, y) projects back to (x, y)) for cameras aimed and rolled every way; with
 * distortion, projecting and unprojecting are each other's inverse; the focal length and the
 * field of view convert both ways; a scene camera converts to heading, pitch and roll and back. */
#include <math.h>

#include "harness.h"
#include "geometry/camera_frame.h"
#include "geometry/camera_project.h"
#include "render/camera.h"

static const double aims[][3] = {
    /* heading, pitch, roll */
    {0, 0, 0}, {90, 0, 0}, {231, -3, 0}, {-45, 20, 10}, {170, -60, -25}, {300, 75, 170}, {12, -89, 5},
};

TEST(agrees_with_render_camera)
{
    for (size_t a = 0; a < sizeof aims / sizeof aims[0]; a++) {
        camera_model m = {.position = {120.0, -35.0, 410.0}, .heading_deg = aims[a][0],
                          .pitch_deg = aims[a][1], .roll_deg = aims[a][2], .fov_deg = 53.0,
                          .width = 1200, .height = 800};
        camera_settings s;
        camera_model_to_settings(&m, &s);
        camera c;
        camera_init(&c, &s, m.width, m.height);
        static const double pixels[][2] = {{600, 400}, {0.5, 0.5}, {1199.5, 799.5}, {37.25, 700.75},
                                           {1000, 50}, {310.5, 420.25}};
        for (size_t i = 0; i < sizeof pixels / sizeof pixels[0]; i++) {
            vec3 d = camera_direction(&c, (float)pixels[i][0], (float)pixels[i][1]);
            for (double dist = 3.0; dist < 1e5; dist *= 40.0) {
                double p[3] = {m.position[0] + dist * d.x, m.position[1] + dist * d.y, m.position[2] + dist * d.z};
                double px[2] = {NAN, NAN};
                CHECK_INT(camera_project(&m, p, px), 0);
                CHECK_NEAR(px[0], pixels[i][0], 1e-3);
                CHECK_NEAR(px[1], pixels[i][1], 1e-3);
            }
            /* and the inverse is the renderer's ray */
            double ray[3];
            CHECK_INT(camera_unproject(&m, pixels[i][0], pixels[i][1], ray), 0);
            CHECK_NEAR(ray[0], d.x, 2e-6);
            CHECK_NEAR(ray[1], d.y, 2e-6);
            CHECK_NEAR(ray[2], d.z, 2e-6);
        }
    }
}

TEST(heading_pitch_roll_as_the_scene_file_means_them)
{
    /* heading 90 looks east; the image's right is then south; the centre projects to the centre */
    camera_model m = {.heading_deg = 90, .fov_deg = 60, .width = 100, .height = 50};
    double f[3], r[3], u[3], px[2];
    camera_model_frame(&m, f, r, u);
    CHECK_NEAR(f[0], 1, 1e-12);
    CHECK_NEAR(r[1], -1, 1e-12);
    CHECK_NEAR(u[2], 1, 1e-12);
    CHECK_INT(camera_project(&m, (double[3]){100, 0, 0}, px), 0);
    CHECK_NEAR(px[0], 50, 1e-9);
    CHECK_NEAR(px[1], 25, 1e-9);
    /* a point to the south-east is right of centre, one above the eye is in the upper half */
    CHECK_INT(camera_project(&m, (double[3]){100, -10, 5}, px), 0);
    CHECK(px[0] > 50 && px[1] < 25);
    /* behind the eye: refused */
    CHECK_INT(camera_project(&m, (double[3]){-100, 0, 0}, px), -1);
    CHECK_INT(camera_project(&m, (double[3]){-0.01, 10, 0}, px), -1);
    /* roll 10: the right side of the camera goes down, so a level point on the right appears
     * higher in the image (the horizon rises to the right) */
    m.roll_deg = 10;
    CHECK_INT(camera_project(&m, (double[3]){100, -20, 0}, px), 0);
    CHECK(px[0] > 50 && px[1] < 25);
}

TEST(focal_length_and_field_of_view)
{
    camera_model m = {.width = 4290, .height = 2856};
    camera_model_set_focal_mm(&m, 30.0, 22.0);
    CHECK_NEAR(m.fov_deg, 2 * atan(22.0 / 60.0) * 180 / M_PI, 1e-12);
    CHECK_NEAR(camera_model_focal_mm(&m, 22.0), 30.0, 1e-12);
    CHECK_NEAR(camera_model_focal_px(&m), 30.0 / 22.0 * 4290, 1e-9);
    camera_model_set_focal_px(&m, 6000);
    CHECK_NEAR(camera_model_focal_px(&m), 6000, 1e-9);
}

TEST(distortion_round_trip)
{
    static const double k[][2] = {{-0.25, 0.1}, {0.15, -0.02}, {-0.08, 0}, {0.3, 0.2}};
    for (size_t j = 0; j < sizeof k / sizeof k[0]; j++) {
        camera_model m = {.position = {5, 6, 7}, .heading_deg = 231, .pitch_deg = -4, .roll_deg = 1.5,
                          .fov_deg = 40, .width = 4290, .height = 2856, .k1 = k[j][0], .k2 = k[j][1]};
        for (double y = 0; y <= 2856; y += 476)
            for (double x = 0; x <= 4290; x += 429) {
                double ray[3], p[3], px[2];
                CHECK_INT(camera_unproject(&m, x, y, ray), 0);
                CHECK_NEAR(ray[0] * ray[0] + ray[1] * ray[1] + ray[2] * ray[2], 1, 1e-12);
                for (int c = 0; c < 3; c++) p[c] = m.position[c] + 700 * ray[c];
                CHECK_INT(camera_project(&m, p, px), 0);
                CHECK_NEAR(px[0], x, 1e-6);
                CHECK_NEAR(px[1], y, 1e-6);
            }
        /* distortion moves the corners and leaves the centre where it is */
        camera_model pin = m;
        pin.k1 = pin.k2 = 0;
        double ray[3], p[3], a[2], b[2];
        CHECK_INT(camera_unproject(&pin, 0, 0, ray), 0);
        for (int c = 0; c < 3; c++) p[c] = m.position[c] + 100 * ray[c];
        camera_project(&m, p, a);
        camera_project(&pin, p, b);
        CHECK(hypot(a[0] - b[0], a[1] - b[1]) > 10);
        CHECK_INT(camera_unproject(&pin, 2145, 1428, ray), 0);
        for (int c = 0; c < 3; c++) p[c] = m.position[c] + 100 * ray[c];
        camera_project(&m, p, a);
        CHECK_NEAR(a[0], 2145, 1e-9);
        CHECK_NEAR(a[1], 1428, 1e-9);
    }
}

TEST(folded_distortion_has_no_ray)
{
    /* k1 = -0.5: x (1 - 0.5 r^2) stops growing at r^2 = 2/3, radius 0.544 on the tangent plane;
     * with a 90 degree field of view the corner is at r = 1.2 -> no ray there */
    camera_model m = {.heading_deg = 0, .fov_deg = 90, .width = 200, .height = 100, .k1 = -0.5};
    double ray[3];
    CHECK_INT(camera_unproject(&m, 0, 0, ray), -1);
    CHECK_INT(camera_unproject(&m, 100, 50, ray), 0);
    CHECK_NEAR(ray[1], 1, 1e-12);
    CHECK_INT(camera_unproject(&m, 130, 50, ray), 0);
}

TEST(from_scene_settings)
{
    /* a look_at camera with a tilted up vector: heading, pitch and roll reproduce its frame */
    camera_settings s = {.position = {1, 2, 3}, .has_look_at = 1, .look_at = {-40, -60, -2},
                         .up = {0.2, 0, 1}, .roll_deg = 7, .fov_deg = 45};
    camera_model m;
    camera_model_from_settings(&m, &s, 640, 480);
    double f0[3], r0[3], u0[3], f1[3], r1[3], u1[3];
    camera_frame(&s, f0, r0, u0);
    camera_model_frame(&m, f1, r1, u1);
    for (int k = 0; k < 3; k++) {
        CHECK_NEAR(f1[k], f0[k], 1e-12);
        CHECK_NEAR(r1[k], r0[k], 1e-12);
        CHECK_NEAR(u1[k], u0[k], 1e-12);
    }
    CHECK_NEAR(m.fov_deg, 45, 0);
    /* straight down, the top of the image to the east */
    camera_settings d = {.position = {0, 0, 50}, .direction = {0, 0, -1}, .up = {1, 0, 0}, .fov_deg = 30};
    camera_model_from_settings(&m, &d, 64, 64);
    CHECK_NEAR(m.pitch_deg, -90, 1e-12);
    CHECK_NEAR(m.heading_deg, 90, 1e-9);
    camera_model_frame(&m, f1, r1, u1);
    camera_frame(&d, f0, r0, u0);
    for (int k = 0; k < 3; k++) CHECK_NEAR(u1[k], u0[k], 1e-9);
}

TEST_LIST(TEST_CASE(agrees_with_render_camera), TEST_CASE(heading_pitch_roll_as_the_scene_file_means_them),
          TEST_CASE(focal_length_and_field_of_view), TEST_CASE(distortion_round_trip),
          TEST_CASE(folded_distortion_has_no_ray), TEST_CASE(from_scene_settings))
