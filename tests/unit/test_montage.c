/* test_montage.c — a photomontage end to end (montage/montage_run.h): a scene rendered without
 * its development stands in for the photograph; ten control points on it (ground points and
 * tree tops, their pixels projected through the true camera) match a camera started 1.2 m,
 * 6 degrees and 7 % of focal length away back to the true one (position within 0.5 m, angles
 * within 0.05 degrees, focal length within 0.5 %), with a pinhole and with a lens of barrel
 * distortion (rendered through it, fitted back); the development composited into that
 * photograph matches the whole scene rendered through the true camera, and so it does into a
 * cylindrical panorama; every file a reviewer needs is written. Also: the start camera from a
 * real photograph's EXIF GPS, and new planting as part of the development. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "harness.h"
#include "io/image_io.h"
#include "montage/composite.h"
#include "montage/montage_run.h"
#include "render/accel.h"
#include "render/camera.h"
#include "render/render.h"
#include "render/wireline.h"
#include "scene_fixture.h"
#include "work_dir.h"

#define SCENE_BODY                                                                                   \
    "sun: {azimuth: 330, elevation: 25}\n"                                                         \
    "sky: {model: constant, color: [0.12, 0.15, 0.2]}\n"                                           \
    "materials:\n"                                                                                 \
    "  grass: {albedo: [0.22, 0.3, 0.12]}\n"                                                       \
    "  concrete: {albedo: [0.7, 0.68, 0.62]}\n"                                                    \
    "  bark: {albedo: [0.3, 0.2, 0.12]}\n"                                                         \
    "  foliage: {albedo: [0.1, 0.25, 0.07]}\n"                                                     \
    "terrain: {origin: [-60, -60], spacing: [40, 40], material: grass,\n"                          \
    "          grid: [[0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]]}\n"                  \
    "species:\n"                                                                                   \
    "  trunk: {shape: box, size: [0.4, 0.4, 3], material: bark}\n"                                 \
    "  crown: {shape: sphere, radius: 1.8, subdivisions: 3, material: foliage}\n"                  \
    "plants:\n"                                                                                    \
    "  - {species: trunk, position: [-1.5, 3, 0]}\n"                                               \
    "  - {species: crown, position: [-1.5, 3, 4]}\n"                                               \
    "  - {species: trunk, position: [2.5, 1, 0]}\n"                                                \
    "  - {species: crown, position: [2.5, 1, 3.6]}\n"                                              \
    "  - {species: trunk, position: [9, 4, 0]}\n"                                                  \
    "  - {species: crown, position: [9, 4, 4.2]}\n"                                                \
    "  - {species: trunk, position: [-1, 8.5, 0], scale: 1.6}\n"                                   \
    "  - {species: crown, position: [-1, 8.5, 6.5], scale: 1.3}\n"                                 \
    "objects:\n"                                                                                   \
    "  - {name: hall, shape: box, size: [8, 5, 7], position: [0, 12, 3.5], material: concrete,\n" \
    "     development: true}\n"

/* the true camera, and the photograph's size and samples */
#define TRUE_CAMERA "camera: {position: [3, -12, 6.5], heading: 3, pitch: -14.5, roll: 0.8, fov: 62}\n"
#define IMAGE "image: {width: 192, height: 120, spp: 64, seed: 11, max_depth: 3}\n"

static double mae(const float *a, const float *b, size_t n)
{
    double s = 0;
    for (size_t i = 0; i < n; i++) s += fabs((double)a[i] - b[i]);
    return s / n;
}

/* The whole round trip with a lens of radial distortion k1 (0: a pinhole): the photograph is
 * rendered through it, the match fits it (fit_distortion) and the montage is rendered with it. */
static void round_trip(double k1)
{
    err_buf err = {{0}};
    /* the "photograph": the scene without its development, another seed, as 8-bit sRGB */
    scene *truth = fixture_scene(work_file("truth.yaml", IMAGE TRUE_CAMERA SCENE_BODY));
    if (!truth) return;
    truth->camera.k1 = k1;
    render_options ro = {.threads = 2, .quiet = 1, .seed_set = 1, .seed = 99, .leave_out = ACCEL_MASK_DEVELOPMENT};
    film *shot = render_scene(truth, &ro, NULL, &err);
    CHECK(shot != NULL);
    if (!shot) return;
    char dir[4096], plate[4096], gcp[4096];
    snprintf(plate, sizeof plate, "%s", work_path("plate.png"));
    CHECK_INT(composite_write_srgb(plate, shot->width, shot->height, shot->rgb, &err), 0);
    /* ten control points seen in it: ground points and the tops of the crowns */
    const double world[10][3] = {{-10, 20, 0}, {15, 25, 0}, {-3, 1, 0}, {10, -2, 0}, {0, 30, 0},
                                 {-1.5, 3, 5.8}, {2.5, 1, 5.4}, {9, 4, 6}, {-1, 8.5, 6.5}, {16, 12, 0}};
    camera_model cam;
    camera_model_from_settings(&cam, &truth->camera, shot->width, shot->height);
    cam.k1 = k1;
    FILE *f = fopen(work_path("gcp.csv"), "w");
    CHECK(f != NULL);
    if (!f) return;
    fprintf(f, "id,u,v,x,y,z\n");
    for (int i = 0; i < 10; i++) {
        double px[2];
        CHECK_INT(camera_project(&cam, world[i], px), 0);
        CHECK(px[0] > 0 && px[0] < shot->width && px[1] > 0 && px[1] < shot->height);
        fprintf(f, "p%d,%.4f,%.4f,%g,%g,%g\n", i, px[0], px[1], world[i][0], world[i][1], world[i][2]);
    }
    fclose(f);
    snprintf(gcp, sizeof gcp, "%s", work_path("gcp.csv"));
    film_free(shot);

    /* the montage's scene: the camera started away from the truth, the focal length 7 % off */
    char text[8192];
    snprintf(text, sizeof text,
             IMAGE "camera: {position: [3.8, -11.2, 6.9], heading: 7, pitch: -12.5, fov: 58}\n"
             "photo: {file: %s, control_points: %s, fit_position: true, fit_distortion: %s}\n" SCENE_BODY, plate,
             gcp, k1 != 0 ? "true" : "false");
    const char *path = work_file("montage.yaml", text);
    scene_file *sf = scene_file_load(path, NULL, &err);
    if (!sf) fprintf(stderr, "%s\n", err.msg);
    CHECK(sf != NULL);
    if (!sf) return;
    build_options bo = {.quiet = 1};
    scene *s = scene_build(sf, NULL, &bo, &err);
    CHECK(s != NULL);
    snprintf(dir, sizeof dir, "%s", work_path("out"));
    mkdir(dir, 0700);
    montage_options mo = {.dir = dir, .threads = 2, .quiet = 1, .dpi = 50};
    montage_report rep;
    int rc = s ? montage_run(s, sf, &mo, &rep, &err) : -1;
    if (rc) fprintf(stderr, "%s\n", err.msg);
    CHECK_INT(rc, 0);
    if (!rc) {
        const camera_model *c = &rep.camera;
        double dp = sqrt(pow(c->position[0] - cam.position[0], 2) + pow(c->position[1] - cam.position[1], 2) +
                         pow(c->position[2] - cam.position[2], 2));
        double df = fabs(camera_model_focal_px(c) / camera_model_focal_px(&cam) - 1);
        fprintf(stderr, "matched: position off %.4f m, heading %.4f, pitch %.4f, roll %.4f deg, focal %.4f %%, "
                        "k1 %.5f (true %.5f), RMSE %.4f px\n", dp, c->heading_deg - cam.heading_deg,
                c->pitch_deg - cam.pitch_deg, c->roll_deg - cam.roll_deg, 100 * df, c->k1, k1, rep.match->rmse_px);
        CHECK(fabs(c->k1 - k1) < 1e-3);
        CHECK(dp < 0.5);
        CHECK(fabs(c->heading_deg - cam.heading_deg) < 0.05 && fabs(c->pitch_deg - cam.pitch_deg) < 0.05 &&
              fabs(c->roll_deg - cam.roll_deg) < 0.05);
        CHECK(df < 0.005);
        /* the montage against the whole scene rendered through the true camera */
        render_options whole = {.threads = 2, .quiet = 1};
        film *ref = render_scene(truth, &whole, NULL, &err);
        image_f32 got = {0};
        char exr[4200];
        snprintf(exr, sizeof exr, "%s/montage.exr", dir);
        CHECK_INT(image_read(exr, &got, &err), 0);
        if (ref && got.pixels && got.width == ref->width) {
            size_t n = (size_t)ref->width * ref->height;
            float *rgb = malloc(n * 3 * sizeof *rgb);
            for (size_t k = 0; rgb && k < n; k++)
                for (int ch = 0; ch < 3; ch++) rgb[3 * k + ch] = got.pixels[k * got.channels + ch];
            double e = rgb ? mae(rgb, ref->rgb, n * 3) : 1;
            fprintf(stderr, "montage against the whole render: MAE %.5f (linear)\n", e);
            CHECK(e < 0.006); /* noise of two 64-spp renders and the photograph's 8-bit steps */
            free(rgb);
        }
        image_free(&got);
        film_free(ref);
        const char *files[] = {"montage.png", "montage.exr", "mask.png", "existing.png", "wireline.png",
                               "sheet.pdf", "sheet.png", "residuals.csv"};
        for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
            char p[4200];
            struct stat st;
            snprintf(p, sizeof p, "%s/%s", dir, files[i]);
            CHECK(stat(p, &st) == 0 && st.st_size > 0);
        }
        montage_report_free(&rep);
    }
    scene_free(s);
    scene_file_free(sf);
    scene_free(truth);
}

/* The renderer's rays go through the lens as the camera model projects: a point along the ray of
 * pixel (x, y) projects back onto (x, y). */
TEST(renderer_rays_follow_the_lens)
{
    camera_settings cs = {.position = {1, 2, 3}, .direction = {0.2, 1, -0.1}, .up = {0, 0, 1}, .fov_deg = 62,
                          .k1 = -0.08, .k2 = 0.01};
    camera c;
    camera_init(&c, &cs, 192, 120);
    CHECK(c.distorted);
    camera_model m = {0};
    camera_model_from_settings(&m, &cs, 192, 120);
    m.k1 = cs.k1, m.k2 = cs.k2;
    double worst = 0;
    for (float y = 0.5f; y < 120; y += 17)
        for (float x = 0.5f; x < 192; x += 23) {
            vec3 d = camera_direction(&c, x, y);
            double p[3] = {1 + 40.0 * d.x, 2 + 40.0 * d.y, 3 + 40.0 * d.z}, px[2];
            CHECK_INT(camera_project(&m, p, px), 0);
            worst = fmax(worst, hypot(px[0] - x, px[1] - y));
        }
    CHECK(worst < 1e-2);
    /* and the lens bends: the corner ray is not the pinhole's */
    camera pin;
    cs.k1 = cs.k2 = 0;
    camera_init(&pin, &cs, 192, 120);
    vec3 a = camera_direction(&c, 0.5f, 0.5f), b = camera_direction(&pin, 0.5f, 0.5f);
    CHECK(v3_dot(a, b) < 0.9999f);
}

TEST(photograph_to_montage) { round_trip(0.0); }

/* A lens that bends straight lines (barrel distortion): the montage is rendered through it. */
TEST(photograph_with_lens_distortion) { round_trip(-0.08); }

/* A cylindrical panorama (120 degrees across) as the photograph: rendered and composited
 * through the scene's camera as it is; control points are refused for it. */
TEST(panorama_montage)
{
    err_buf err = {{0}};
#define PANO_CAMERA "camera: {position: [3, -12, 6.5], heading: 3, pitch: -10, projection: cylindrical, fov: 120}\n"
#define PANO_IMAGE "image: {width: 240, height: 80, spp: 64, seed: 11, max_depth: 3}\n"
    scene *truth = fixture_scene(work_file("pano_truth.yaml", PANO_IMAGE PANO_CAMERA SCENE_BODY));
    if (!truth) return;
    render_options ro = {.threads = 2, .quiet = 1, .seed_set = 1, .seed = 99, .leave_out = ACCEL_MASK_DEVELOPMENT};
    film *shot = render_scene(truth, &ro, NULL, &err);
    render_options whole = {.threads = 2, .quiet = 1};
    film *ref = render_scene(truth, &whole, NULL, &err);
    CHECK(shot && ref);
    if (!shot || !ref) return;
    char plate[4096], dir[4096], text[8192];
    snprintf(plate, sizeof plate, "%s", work_path("pano.png"));
    CHECK_INT(composite_write_srgb(plate, shot->width, shot->height, shot->rgb, &err), 0);
    snprintf(text, sizeof text, PANO_IMAGE PANO_CAMERA "photo: {file: %s}\n" SCENE_BODY, plate);
    scene_file *sf = scene_file_load(work_file("pano.yaml", text), NULL, &err);
    CHECK(sf != NULL);
    build_options bo = {.quiet = 1};
    scene *s = sf ? scene_build(sf, NULL, &bo, &err) : NULL;
    CHECK(s != NULL);
    snprintf(dir, sizeof dir, "%s", work_path("pano_out"));
    mkdir(dir, 0700);
    montage_options mo = {.dir = dir, .threads = 2, .quiet = 1, .dpi = 50};
    montage_report rep;
    int rc = s ? montage_run(s, sf, &mo, &rep, &err) : -1;
    if (rc) fprintf(stderr, "%s\n", err.msg);
    CHECK_INT(rc, 0);
    if (!rc) {
        image_f32 got = {0};
        char exr[4200];
        snprintf(exr, sizeof exr, "%s/montage.exr", dir);
        CHECK_INT(image_read(exr, &got, &err), 0);
        size_t n = (size_t)ref->width * ref->height;
        float *rgb = malloc(n * 3 * sizeof *rgb);
        for (size_t k = 0; rgb && got.pixels && k < n; k++)
            for (int ch = 0; ch < 3; ch++) rgb[3 * k + ch] = got.pixels[k * got.channels + ch];
        double e = rgb && got.pixels ? mae(rgb, ref->rgb, n * 3) : 1;
        fprintf(stderr, "panorama montage against the whole render: MAE %.5f (linear)\n", e);
        CHECK(e < 0.006);
        free(rgb);
        image_free(&got);
        montage_report_free(&rep);
    }
    /* control points cannot match a panorama */
    if (s) {
        mo.points = work_file("pano_gcp.csv", "u,v,x,y,z\n1,2,3,4,5\n");
        CHECK_INT(montage_run(s, sf, &mo, &rep, &err), -1);
        CHECK_STR_CONTAINS(err.msg, "the camera match solves a perspective camera");
    }
    scene_free(s);
    scene_file_free(sf);
    film_free(shot);
    film_free(ref);
    scene_free(truth);
}

/* New planting is part of the development: a plant marked `development: true` is composited
 * with it (its coverage and radiance in the development's layers), left out of the render
 * without it, and outlined by the wireline; the other plants are not. */
TEST(new_planting_is_part_of_the_development)
{
    scene *s = fixture_scene(work_file("planting.yaml",
        "image: {width: 96, height: 64, spp: 4, seed: 1}\n"
        "camera: {position: [0, -20, 3], look_at: [0, 0, 2], fov: 50}\n"
        "terrain: {grid: [[0, 0], [0, 0]], origin: [-50, -50], spacing: [100, 100]}\n"
        "species: {hedge: {shape: box, size: [2, 2, 6]}}\n"
        "plants:\n"
        "  - {species: hedge, position: [-4, 0], development: true}\n"
        "  - {species: hedge, position: [4, 0]}\n"));
    if (!s) return;
    err_buf err = {{0}};
    render_options ro = {.threads = 2, .quiet = 1};
    composite_renders r;
    CHECK_INT(composite_render(s, &ro, &r, &err), 0);
    if (!r.full) return;
    /* coverage on the left (the new hedge), none on the right (the old one) */
    double left = 0, right = 0;
    for (uint32_t y = 0; y < 64; y++)
        for (uint32_t x = 0; x < 96; x++) {
            float a = r.full->development[y * 96 + x];
            if (x < 48) left += a;
            else right += a;
        }
    CHECK(left > 50 && right == 0);
    /* left out of the render without the development: the background there is the ground */
    uint32_t differs = 0;
    for (uint32_t k = 0; k < 96 * 64; k++) differs += r.full->development[k] > 0.99f && r.background->object_id[k] == 0 &&
                                                      r.background->instance_id[k] == 0;
    CHECK(differs > 50);
    camera cam;
    camera_init(&cam, &s->camera, 96, 64);
    wireline w;
    CHECK_INT(wireline_find(&w, r.full, s, &cam, &err), 0);
    CHECK(w.outline > 20);
    wireline_free(&w);
    composite_renders_free(&r);
    scene_free(s);
}

/* camera_from_exif: the match starts at the photograph's GPS position, altitude and direction
 * (the iPhone 6s photograph of ../shared/data: 52.2096778 N, 0.8955306 W, 103.64 m, 109.81 deg;
 * gdaltransform puts it at E 643788.979, N 5786446.821 in UTM zone 30N), with the focal length
 * of its EXIF on the sensor width its 35 mm equivalent gives. */
TEST(start_camera_from_exif)
{
    const char *train = SYLVA_SHARED_DATA_DIR "/photos/lychee/train.jpg";
    FILE *probe = fopen(train, "rb");
    if (!probe) {
        SKIP("no shared data (../shared/data/photos)");
        return;
    }
    fclose(probe);
    err_buf err = {{0}};
    char text[2048];
    snprintf(text, sizeof text,
             "site: {crs: EPSG:32630, origin: [643000, 5786000]}\n"
             "camera: {position: [0, 0, 2], heading: 0, fov: 40}\n"
             "photo: {file: %s, camera_from_exif: true}\n", train);
    scene_file *sf = scene_file_load(work_file("exif.yaml", text), NULL, &err);
    if (!sf) fprintf(stderr, "%s\n", err.msg);
    CHECK(sf != NULL);
    build_options bo = {.quiet = 1};
    scene *s = sf ? scene_build(sf, NULL, &bo, &err) : NULL;
    photo ph = {0};
    CHECK_INT(photo_read(train, &ph, &err), 0);
    camera_model m = {0};
    double sensor = 0;
    CHECK_INT(s ? montage_start_camera(s, sf, &ph, &m, &sensor, &err) : -1, 0);
    CHECK_NEAR(m.position[0], 788.979, 0.01);
    CHECK_NEAR(m.position[1], 446.821, 0.01);
    CHECK_NEAR(m.position[2], 103.64, 0.01);
    CHECK_NEAR(m.heading_deg, 109.8107, 1e-3);
    CHECK_NEAR(sensor, 4.953, 0.001);
    CHECK_NEAR(m.fov_deg, 2 * atan(sensor / (2 * 4.15)) * 180 / M_PI, 1e-5);
    photo_free(&ph);
    scene_free(s);
    scene_file_free(sf);
}

/* Without a photo: section, a plate sylva rendered is composited with a gain of 1 (its light is
 * the render's own); a photograph is refused before anything is rendered, saying what to add. */
TEST(plate_without_photo_section)
{
    err_buf err = {{0}};
#define SMALL_IMAGE "image: {width: 48, height: 30, spp: 4, seed: 11, max_depth: 2}\n"
    const char *path = work_file("no_photo.yaml", SMALL_IMAGE TRUE_CAMERA SCENE_BODY);
    scene_file *sf = path ? scene_file_load(path, NULL, &err) : NULL;
    build_options bo = {.quiet = 1};
    scene *s = sf ? scene_build(sf, NULL, &bo, &err) : NULL;
    CHECK(s != NULL);
    if (!s) {
        scene_file_free(sf);
        return;
    }
    render_options ro = {.threads = 2, .quiet = 1, .leave_out = ACCEL_MASK_DEVELOPMENT};
    film *shot = render_scene(s, &ro, NULL, &err);
    CHECK(shot != NULL);
    char plate[4096], snapshot[4096], dir[4096];
    snprintf(plate, sizeof plate, "%s", work_path("own_plate.png"));
    CHECK_INT(shot ? composite_write_srgb(plate, shot->width, shot->height, shot->rgb, &err) : -1, 0);
    snprintf(snapshot, sizeof snapshot, "%s", SYLVA_TEST_DATA_DIR "/image/plain_photo.png"); /* no sylva tag */
    snprintf(dir, sizeof dir, "%s", work_path("no_photo_out"));
    mkdir(dir, 0700);
    montage_options mo = {.dir = dir, .threads = 2, .quiet = 1, .dpi = 50, .photo = plate};
    montage_report rep;
    int rc = montage_run(s, sf, &mo, &rep, &err);
    if (rc) fprintf(stderr, "%s\n", err.msg);
    CHECK_INT(rc, 0);
    if (!rc) montage_report_free(&rep);
    mo.photo = snapshot;
    double t0 = harness_seconds();
    CHECK_INT(montage_run(s, sf, &mo, &rep, &err), -1);
    CHECK(harness_seconds() - t0 < 0.5); /* refused before any render */
    CHECK_INT(err.status, ERR_USAGE);
    CHECK_STR_CONTAINS(err.msg, "plain_photo.png is a photograph and the scene has no photo: section");
    CHECK_STR_CONTAINS(err.msg, "add photo: {file: ");
    film_free(shot);
    scene_free(s);
    scene_file_free(sf);
}

TEST_LIST(TEST_CASE(renderer_rays_follow_the_lens), TEST_CASE(start_camera_from_exif), TEST_CASE(plate_without_photo_section),
          TEST_CASE(new_planting_is_part_of_the_development),
          TEST_CASE(panorama_montage), TEST_CASE(photograph_to_montage), TEST_CASE(photograph_with_lens_distortion))
