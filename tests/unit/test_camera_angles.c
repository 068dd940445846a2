/* test_camera_angles.c — the camera aimed by heading and pitch and turned by roll
 * (scene_file/scene_file_settings.c, geometry/camera_frame.h): heading 90 is the view of a look_at due
 * east, a view straight down keeps its heading at the top of the image, and a roll turns the
 * rendered image about its centre the documented way. The POV-Ray side is checked by the
 * cross-check scene tests/scenes/crosscheck/rolled_camera.yaml. */
#include <math.h>

#include "harness.h"
#include "work_dir.h"
#include "geometry/camera_frame.h"
#include "render/camera.h"
#include "render/film.h"
#include "render/render.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"

/* The scene file `text` written to the work folder and loaded; NULL (after a failed CHECK) when
 * it does not load. */
static scene_file *load_text(const char *name, const char *text)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/%s", work_dir(), name);
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f) return NULL;
    fputs(text, f);
    fclose(f);
    err_buf err = {{0}};
    scene_file *sf = scene_file_load(path, NULL, &err);
    if (!sf) fprintf(stderr, "%s\n", err.msg);
    CHECK(sf != NULL);
    return sf;
}

static void check_vec(const double got[3], double x, double y, double z, double tol)
{
    CHECK_NEAR(got[0], x, tol);
    CHECK_NEAR(got[1], y, tol);
    CHECK_NEAR(got[2], z, tol);
}

TEST(heading_90_is_look_at_east)
{
    scene_file *a = load_text("heading.yaml", "camera: {position: [5, 7, 2], heading: 90}\n");
    scene_file *b = load_text("look_at.yaml", "camera: {position: [5, 7, 2], look_at: [105, 7, 2]}\n");
    if (a && b) {
        double fa[3], ra[3], ua[3], fb[3], rb[3], ub[3];
        camera_frame(&a->camera, fa, ra, ua);
        camera_frame(&b->camera, fb, rb, ub);
        check_vec(fa, fb[0], fb[1], fb[2], 1e-12);
        check_vec(ra, rb[0], rb[1], rb[2], 1e-12);
        check_vec(ua, ub[0], ub[1], ub[2], 1e-12);
        check_vec(fa, 1, 0, 0, 1e-12);
        check_vec(ra, 0, -1, 0, 1e-12); /* facing east, the right hand points south */
        /* The renderer's rays agree too: the centre of the image looks east. */
        camera ca, cb;
        camera_init(&ca, &a->camera, 64, 48);
        camera_init(&cb, &b->camera, 64, 48);
        vec3 da = camera_direction(&ca, 10.5f, 40.5f), db = camera_direction(&cb, 10.5f, 40.5f);
        CHECK_NEAR(da.x, db.x, 1e-6);
        CHECK_NEAR(da.y, db.y, 1e-6);
        CHECK_NEAR(da.z, db.z, 1e-6);
    }
    scene_file_free(a);
    scene_file_free(b);
}

TEST(pitch_and_heading)
{
    /* 30 degrees up toward the south-west */
    scene_file *a = load_text("sw.yaml", "camera: {position: [0, 0, 2], heading: 225, pitch: 30}\n");
    /* straight down, heading north-east at the top of the image */
    scene_file *b = load_text("down.yaml", "camera: {position: [0, 0, 50], heading: 45, pitch: -90}\n");
    if (a && b) {
        double f[3], r[3], u[3], s = sqrt(0.5);
        camera_frame(&a->camera, f, r, u);
        check_vec(f, -s * cos(M_PI / 6), -s * cos(M_PI / 6), 0.5, 1e-12);
        CHECK_NEAR(r[2], 0, 1e-12); /* no roll: the right hand stays level */
        CHECK(u[2] > 0);
        camera_frame(&b->camera, f, r, u);
        check_vec(f, 0, 0, -1, 1e-12);
        check_vec(u, s, s, 0, 1e-12);
        check_vec(r, s, -s, 0, 1e-12);
    }
    scene_file_free(a);
    scene_file_free(b);
}

/* The mean pixel position of the pixels whose centre ray sees the object. */
static int object_centroid(const film *f, double *x, double *y)
{
    double sx = 0, sy = 0, n = 0;
    for (uint32_t j = 0; j < f->height; j++)
        for (uint32_t i = 0; i < f->width; i++)
            if (f->pixel_class[(size_t)j * f->width + i] == PIXEL_OBJECT) sx += i + 0.5, sy += j + 0.5, n++;
    if (n == 0) return -1;
    *x = sx / n, *y = sy / n;
    return 0;
}

/* A small sphere up and to the right of the view's centre; with roll r (clockwise camera) the
 * image turns counter-clockwise by r about its centre: a point at (u, v) from the centre (v up)
 * moves to (u cos r - v sin r, v cos r + u sin r). */
TEST(roll_turns_the_image)
{
    const char *text = "image: {width: 200, height: 200, spp: 1}\n"
                       "camera: {position: [0, 0, 0], heading: 0, pitch: 0, roll: %g, fov: 40}\n"
                       "sky: {model: constant}\n"
                       "objects:\n  - {shape: sphere, radius: 1.5, subdivisions: 3, position: [12, 60, 5]}\n";
    double cx[2], cy[2], roll[2] = {0, 35};
    for (int k = 0; k < 2; k++) {
        char buf[512], name[32];
        snprintf(buf, sizeof buf, text, roll[k]);
        snprintf(name, sizeof name, "roll%d.yaml", k);
        scene_file *sf = load_text(name, buf);
        if (!sf) return;
        CHECK_NEAR(sf->camera.roll_deg, roll[k], 0);
        err_buf err = {{0}};
        build_options bo = {.quiet = 1};
        scene *s = scene_build(sf, NULL, &bo, &err);
        scene_file_free(sf);
        CHECK(s != NULL);
        if (!s) return;
        render_options ro = {.threads = 1, .verify = 1, .quiet = 1};
        film *f = render_scene(s, &ro, NULL, &err);
        CHECK(f != NULL);
        CHECK(f && object_centroid(f, &cx[k], &cy[k]) == 0);
        film_free(f);
        scene_free(s);
    }
    double u = cx[0] - 100, v = 100 - cy[0], r = roll[1] * M_PI / 180;
    double want_x = 100 + u * cos(r) - v * sin(r), want_y = 100 - (v * cos(r) + u * sin(r));
    fprintf(stderr, "sphere at (%.2f, %.2f); rolled %g deg: (%.2f, %.2f), expected (%.2f, %.2f)\n", cx[0], cy[0],
            roll[1], cx[1], cy[1], want_x, want_y);
    CHECK(u > 20 && v > 5); /* up and to the right, far enough from the centre to tell */
    CHECK_NEAR(cx[1], want_x, 0.5);
    CHECK_NEAR(cy[1], want_y, 0.5);
}

TEST_LIST(TEST_CASE(heading_90_is_look_at_east), TEST_CASE(pitch_and_heading), TEST_CASE(roll_turns_the_image))
