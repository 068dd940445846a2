/* test_lens.c — the thin lens and the vignette (render/lens.h): lens rays pass through the point
 * in focus and leave from the pupil; an edge at the focus distance stays sharp and one off it
 * blurs as wide as the thin lens says; a vignetted white sky falls off as cos^4; a lens renders
 * the same bytes on one thread as on two; f_number without focus_distance is refused. */
#include "harness.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "geometry/camera_frame.h"
#include "render/lens.h"
#include "scene_text.h"

static camera_settings settings(double f_number, double focus, double vignette)
{
    camera_settings s = {.position = {0, 0, 0}, .direction = {0, 1, 0}, .up = {0, 0, 1}, .fov_deg = 0,
                         .focal_length_mm = 50, .sensor_width_mm = 36, .f_number = f_number,
                         .focus_distance = focus, .vignette = vignette};
    s.fov_deg = 2.0 * atan(36.0 / 100.0) * 180.0 / M_PI;
    return s;
}

TEST(pupil_and_focus)
{
    camera_settings s = settings(2.0, 7.0, 0.0);
    CHECK_NEAR(camera_lens_radius(&s), 0.0125, 1e-9); /* 50 mm at f/2: a 25 mm pupil */
    s.focal_length_mm = 0.0;                            /* implied by fov and the sensor */
    CHECK_NEAR(camera_lens_radius(&s), 0.0125, 1e-9);
    s.f_number = 0.0;
    CHECK_NEAR(camera_lens_radius(&s), 0.0, 0.0);
    s = settings(2.0, 7.0, 0.0);
    camera c;
    camera_init(&c, &s, 64, 48);
    for (int k = 0; k < 200; k++) {
        float u1 = (float)fmod(k * 0.618034, 1.0), u2 = (k + 0.5f) / 200;
        vec3 d = camera_direction(&c, 5.0f + k % 50, 40.0f - k % 30), o;
        vec3 focus = v3_scale(d, 7.0f / v3_dot(d, c.forward));
        vec3 dl = d;
        lens_ray(&c, u1, u2, &o, &dl);
        CHECK(v3_len(o) <= 0.0125f * 1.0001f);
        CHECK_NEAR(v3_dot(o, c.forward), 0.0, 1e-7);        /* on the pupil, across the view */
        vec3 miss = v3_cross(v3_sub(focus, o), dl);            /* the ray passes the focus point */
        CHECK(v3_len(miss) < 1e-5f);
    }
}

/* The sky's light through a row across a black box whose left edge stands on the view axis. */
static void edge_row(double f_number, double focus, float *row, uint32_t w)
{
    char text[1024], lens[96] = "";
    if (f_number > 0.0) snprintf(lens, sizeof lens, ", f_number: %g, focus_distance: %g", f_number, focus);
    snprintf(text, sizeof text,
             "image: {width: %u, height: 8, spp: 256, seed: 3, max_depth: 2}\n"
             "camera: {position: [0, 0, 0], direction: [0, 1, 0], focal_length: 50%s}\n"
             "sun: {enabled: false}\n"
             "sky: {model: constant, color: [1, 1, 1]}\n"
             "materials:\n  black: {albedo: [0, 0, 0]}\n"
             "objects:\n  - {name: wall, shape: box, size: [40, 0.1, 40], position: [20, 20, 0], material: black}\n",
             w, lens);
    scene *s = scene_text_build_ok(text);
    film *f = s ? scene_text_render(s) : NULL;
    for (uint32_t x = 0; x < w; x++) row[x] = f ? f->rgb[((size_t)4 * w + x) * 3 + 1] : NAN;
    /* the lens's samples are keyed by pixel and sample: the same bytes on one thread */
    render_options one = {.threads = 1, .quiet = 1};
    err_buf err = {{0}};
    film *g = s ? render_scene(s, &one, NULL, &err) : NULL;
    CHECK(f && g && !memcmp(f->rgb, g->rgb, (size_t)w * 8 * 3 * sizeof(float)));
    film_free(g);
    film_free(f);
    scene_free(s);
}

/* Pixels over which the row falls from 0.9 to 0.1. */
static int edge_width(const float *row, uint32_t w)
{
    int first = -1, last = -1;
    for (uint32_t x = 0; x < w; x++) {
        if (row[x] < 0.9f && first < 0) first = (int)x;
        if (row[x] > 0.1f) last = (int)x;
    }
    return last - first + 1;
}

TEST(edge_sharp_in_focus_blurred_out_of_it)
{
    enum { W = 64 };
    float pin[W], sharp[W], blur[W];
    edge_row(0.0, 0.0, pin, W);
    edge_row(1.4, 20.0, sharp, W);
    edge_row(1.4, 0.5, blur, W);
    CHECK(edge_width(pin, W) <= 2);
    CHECK(edge_width(sharp, W) <= 2);
    /* out of focus: the pupil (50 / 1.4 mm) through the point in focus at 0.5 m spreads over
     * D (z - F) / F = 1.39 m at 20 m, 0.070 rad; a pixel spans 0.0112 rad: about 6 pixels
     * across, 10 % to 90 % over about 4 of them */
    int bw = edge_width(blur, W);
    CHECK(bw >= 3 && bw <= 7);
    CHECK_NEAR(blur[W / 2 - 1] + blur[W / 2], pin[W / 2 - 1] + pin[W / 2], 0.1);
    for (int x = 1; x < W; x++) CHECK(blur[x] <= blur[x - 1] + 0.05f);
}

TEST(vignette_falls_off_as_cos4)
{
    scene *s = scene_text_build_ok("image: {width: 40, height: 30, spp: 4, seed: 1, max_depth: 1}\n"
                                   "camera: {position: [0, 0, 0], direction: [0, 1, 0], fov: 90, vignette: 1}\n"
                                   "sun: {enabled: false}\n"
                                   "sky: {model: constant, color: [1, 1, 1]}\n");
    film *f = s ? scene_text_render(s) : NULL;
    if (f) {
        camera c;
        camera_init(&c, &s->camera, 40, 30);
        for (uint32_t y = 0; y < 30; y += 7)
            for (uint32_t x = 0; x < 40; x += 9) {
                vec3 d = camera_direction(&c, x + 0.5f, y + 0.5f);
                float k = v3_dot(d, c.forward);
                CHECK_NEAR(f->rgb[((size_t)y * 40 + x) * 3], k * k * k * k, 0.02);
            }
        CHECK(f->rgb[0] < 0.35f); /* the corner, 46 degrees off the axis: cos^4 = 0.23 */
    }
    film_free(f);
    scene_free(s);
}

TEST(f_number_needs_a_focus_distance)
{
    err_buf err = {{0}};
    scene *s = scene_text_build("camera: {position: [0, 0, 2], direction: [0, 1, 0], f_number: 2.8}\n", &err);
    CHECK(s == NULL);
    CHECK_STR_CONTAINS(err.msg, "'f_number' 2.8 needs 'focus_distance'");
    scene_free(s);
}

TEST_LIST(TEST_CASE(pupil_and_focus), TEST_CASE(edge_sharp_in_focus_blurred_out_of_it),
          TEST_CASE(vignette_falls_off_as_cos4), TEST_CASE(f_number_needs_a_focus_distance))
