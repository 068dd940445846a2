/* test_furnace.c — the path tracer's light sampling against closed forms, rendered in-process:
 * a white box under a constant sky (the furnace: every pixel is the albedo, without noise when
 * the constant sky is left to BSDF sampling), and a flat ground under sun and sky, whose
 * radiance is albedo / pi times the irradiance (mean and noise). */
#include <math.h>

#include "geometry/light_summary.h"
#include "harness.h"
#include "scene_build/shapes.h"
#include "scene_text.h"

#define SIZE 16

static void add_shape(scene *s, const char *name, const shape_spec *spec, int32_t mat)
{
    err_buf err = {{0}};
    mesh *m = mesh_new();
    CHECK(m && shape_build(spec, mat, m, &err) == 0);
    scene_add_object(s, name, m, &err);
    CHECK(!err.msg[0]);
}

/* Mean and standard deviation over the pixels of channel G. */
static void pixel_stats(const film *f, double *mean, double *sd)
{
    double sum = 0, sq = 0;
    int n = SIZE * SIZE;
    for (int i = 0; i < n; i++) {
        double g = f->rgb[3 * i + 1];
        sum += g, sq += g * g;
    }
    *mean = sum / n;
    *sd = sqrt(fmax(0.0, sq / n - *mean * *mean));
}

/* The furnace: a box of albedo 0.8 (a convex object: every bounce leaves it) under a constant
 * sky of radiance 1, seen face on, 16 spp. Every pixel is 0.8. Sampling the constant sky as a
 * light over the whole sphere gave a pixel noise of 0.013; BSDF sampling alone (cosine-weighted
 * for a Lambertian surface) sees exactly the albedo on every path: noise under 1e-5. The image
 * is the same bytes on one and on two threads. */
TEST(constant_sky_is_reached_by_bsdf_sampling)
{
    scene *s = scene_new();
    s->image = (image_settings){.width = SIZE, .height = SIZE, .spp = 16, .max_depth = 8, .seed = 5};
    s->camera = (camera_settings){.position = {0, -10, 0}, .direction = {0, 1, 0}, .up = {0, 0, 1}, .fov_deg = 6};
    s->sun = (sun_settings){.enabled = 0, .direction = {0, 0, 1}};
    s->sky = (sky_settings){.model = SKY_CONSTANT, .scale = 1, .color = {1, 1, 1}};
    shape_spec box = {.kind = SHAPE_BOX, .size = {6, 6, 6}};
    add_shape(s, "cube", &box, scene_text_lambert(s, "white", 0.8));
    film *one = scene_text_render_on(s, 1), *two = scene_text_render_on(s, 2);
    if (one && two) {
        double mean, sd;
        pixel_stats(one, &mean, &sd);
        fprintf(stderr, "  furnace: mean %.6f, pixel noise %.6f (albedo 0.8)\n", mean, sd);
        CHECK_NEAR(mean, 0.8, 1e-4);
        CHECK(sd < 1e-5);
        CHECK(memcmp(one->rgb, two->rgb, sizeof(float) * 3 * SIZE * SIZE) == 0);
    }
    film_free(one);
    film_free(two);
    scene_free(s);
}

/* The irradiance of the sky model on a surface facing up (midpoint rule in cos theta, phi). */
static double sky_irradiance_up(const sun_settings *sun, const sky_settings *sky)
{
    light_summary l;
    err_buf err = {{0}};
    CHECK(light_summary_init(&l, sun, sky, 0, 0, 0, &err) == 0);
    const int nc = 400, np = 800;
    double e = 0;
    for (int a = 0; a < nc; a++) {
        double ct = (a + 0.5) / nc, st = sqrt(1 - ct * ct);
        for (int b = 0; b < np; b++) {
            double phi = 2 * M_PI * (b + 0.5) / np;
            vec3 c = light_summary_sky(&l, v3((float)(st * cos(phi)), (float)(st * sin(phi)), (float)ct));
            e += c.y * ct;
        }
    }
    return e * 2 * M_PI / ((double)nc * np);
}

/* Flat ground of albedo 0.5 (a 400 m square seen straight down from 5 m) under the sun at 40
 * degrees (irradiance 1, its 0.53-degree disc) and a sky: constant 0.3, then Preetham's. Every
 * bounce leaves the ground, so each pixel is 0.5 / pi (E_sun sin 40 + E_sky), E_sky the sky's
 * irradiance (pi 0.3 for the constant one). The mean over 256 pixels at 16 spp must lie within
 * 0.5 % (constant sky) and 1 % (Preetham's, tabulated in 2.8-degree cells) of it: next-event
 * estimation and BSDF sampling share the light without bias. */
TEST(ground_under_sun_and_sky)
{
    for (int model = 0; model < 2; model++) {
        scene *s = scene_new();
        s->image = (image_settings){.width = SIZE, .height = SIZE, .spp = 16, .max_depth = 4, .seed = 3};
        s->camera = (camera_settings){.position = {0, 0, 5}, .direction = {0, 0, -1}, .up = {0, 1, 0}, .fov_deg = 20};
        double el = 40 * M_PI / 180;
        s->sun = (sun_settings){.enabled = 1, .direction = {0, cos(el), sin(el)}, .irradiance = 1,
                                .color = {1, 1, 1}, .angular_diameter_deg = 0.53};
        if (model == 0)
            s->sky = (sky_settings){.model = SKY_CONSTANT, .scale = 1, .color = {0.3, 0.3, 0.3}};
        else
            s->sky = (sky_settings){.model = SKY_PREETHAM, .turbidity = 3, .scale = 1, .ground_albedo = 0.2};
        shape_spec quad = {.kind = SHAPE_QUAD, .size = {400, 400}};
        add_shape(s, "ground", &quad, scene_text_lambert(s, "grey", 0.5));
        double expect = 0.5 / M_PI * (sin(el) + sky_irradiance_up(&s->sun, &s->sky));
        film *f = scene_text_render_on(s, 2);
        if (f) {
            double mean, sd;
            pixel_stats(f, &mean, &sd);
            fprintf(stderr, "  %s sky: mean %.5f (expected %.5f), pixel noise %.5f\n", model ? "Preetham" : "constant",
                    mean, expect, sd);
            CHECK_NEAR(mean / expect, 1.0, model ? 0.01 : 0.005);
        }
        film_free(f);
        scene_free(s);
    }
}

TEST_LIST(TEST_CASE(constant_sky_is_reached_by_bsdf_sampling), TEST_CASE(ground_under_sun_and_sky))
