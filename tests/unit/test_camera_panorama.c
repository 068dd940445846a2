/* test_camera_panorama.c — the cylindrical camera (render/camera.h): the angle across is linear
 * in x, the tangent of the elevation linear in y at the scale that keeps pixels square at the
 * horizon, the view direction at the image's centre, and the scene file's keys (a perspective
 * camera refuses 180 degrees, a focal length gives sensor / f radians across). */
#include <math.h>
#include <string.h>

#include "harness.h"
#include "render/camera.h"
#include "scene_file/scene_file.h"
#include "work_dir.h"

static camera panorama(double fov, uint32_t w, uint32_t h)
{
    camera_settings s = {.position = {1, 2, 3}, .direction = {0, 1, 0}, .up = {0, 0, 1}, .cylindrical = 1,
                         .fov_deg = fov};
    camera c;
    camera_init(&c, &s, w, h);
    return c;
}

TEST(angle_across_is_linear_in_x)
{
    camera c = panorama(180, 360, 90);
    for (int x = 0; x <= 360; x += 45) {
        vec3 d = camera_direction(&c, (float)x, 45.0f); /* the middle row: the horizon */
        double az = atan2(d.x, d.y) * 180 / M_PI;      /* clockwise from north (+y), right is +x */
        CHECK_NEAR(az, (x / 360.0 - 0.5) * 180, 1e-4);
        CHECK_NEAR(d.z, 0, 1e-6);
    }
    camera full = panorama(360, 360, 90);
    vec3 back = camera_direction(&full, 0.0f, 45.0f);
    CHECK_NEAR(back.y, -1, 1e-6); /* a full turn: the left edge looks behind */
}

/* The angle between two unit vectors, well conditioned for small angles. */
static double angle_between(vec3 a, vec3 b)
{
    double cx = (double)a.y * b.z - (double)a.z * b.y, cy = (double)a.z * b.x - (double)a.x * b.z,
           cz = (double)a.x * b.y - (double)a.y * b.x;
    return atan2(sqrt(cx * cx + cy * cy + cz * cz), (double)a.x * b.x + (double)a.y * b.y + (double)a.z * b.z);
}

TEST(tangent_of_elevation_is_linear_in_y)
{
    camera c = panorama(90, 400, 200); /* 90 degrees across: the top row at tan = pi / 4 * 200 / 400 */
    double top = M_PI / 4 * 200 / 400;
    for (int y = 0; y <= 200; y += 25) {
        vec3 d = camera_direction(&c, 200.0f, (float)y);
        double t = d.z / sqrt(d.x * d.x + d.y * d.y);
        CHECK_NEAR(t, (1 - 2.0 * y / 200) * top, 1e-5);
    }
    /* square pixels at the horizon: one pixel across and one down span the same angle */
    vec3 a = camera_direction(&c, 200.0f, 100.0f), r = camera_direction(&c, 201.0f, 100.0f),
         u = camera_direction(&c, 200.0f, 99.0f);
    CHECK_NEAR(angle_between(a, r), angle_between(a, u), 1e-7);
    CHECK_NEAR(angle_between(a, r), M_PI / 2 / 400, 1e-7);
    CHECK_NEAR(camera_smallest_pixel_angle(&c), M_PI / 2 / 400 / (1 + top * top), 1e-9);
}

TEST(scene_file_keys)
{
    err_buf err = {{0}};
    const char *path = work_file("pano.yaml", "camera: {position: [0, 0, 2], projection: cylindrical, focal_length: 12,"
                                              " sensor_width: 36}\n");
    scene_file *sf = path ? scene_file_load(path, NULL, &err) : NULL;
    CHECK(sf != NULL);
    if (sf) {
        CHECK_INT(sf->camera.cylindrical, 1);
        CHECK_NEAR(sf->camera.fov_deg, 3.0 * 180 / M_PI, 1e-9); /* 36 / 12 radians */
        scene_file_free(sf);
    }
    path = work_file("wide.yaml", "camera: {position: [0, 0, 2], fov: 200}\n");
    CHECK(path && scene_file_load(path, NULL, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "wide.yaml:1:36: a perspective camera sees less than 180 degrees across, got fov 200");
    path = work_file("turns.yaml", "camera: {position: [0, 0, 2], projection: cylindrical, focal_length: 5}\n");
    CHECK(path && scene_file_load(path, NULL, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "would see 413 degrees across, more than a full turn");
}

TEST_LIST(TEST_CASE(angle_across_is_linear_in_x), TEST_CASE(tangent_of_elevation_is_linear_in_y),
          TEST_CASE(scene_file_keys))
