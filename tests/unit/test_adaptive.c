/* test_adaptive.c — adaptive sampling (image.noise_target, integrator.c), rendered in-process:
 * its two limits are the fixed sample counts, byte for byte; between them pixels stop at
 * different counts, the same on one and two threads, and the error stays near the target. */
#include <math.h>

#include "harness.h"
#include "scene_build/shapes.h"
#include "scene_text.h"

#define SIZE 16

/* A grey sphere on grey ground under the sun and a constant sky, seen from above at an angle:
 * soft sky occlusion and a shadow edge (noisy pixels) beside open ground and sky (smooth ones). */
static scene *sphere_scene(void)
{
    scene *s = scene_new();
    err_buf err = {{0}};
    s->image = (image_settings){.width = SIZE, .height = SIZE, .spp = 16, .max_depth = 3, .seed = 9};
    s->camera = (camera_settings){.position = {0, -6, 3}, .direction = {0, 6, -2.5}, .up = {0, 0, 1}, .fov_deg = 40};
    double el = 35 * M_PI / 180;
    s->sun = (sun_settings){.enabled = 1, .direction = {0.5 * cos(el), 0.866 * cos(el), sin(el)}, .irradiance = 1,
                            .color = {1, 1, 1}, .angular_diameter_deg = 0.53};
    s->sky = (sky_settings){.model = SKY_CONSTANT, .scale = 1, .color = {0.3, 0.35, 0.45}};
    sylva_material_desc grey = {.size = sizeof grey, .name = "grey", .bsdf = SYLVA_BSDF_LAMBERT,
                                .albedo = {0.5, 0.5, 0.5}, .texture = -1};
    int32_t mat = scene_add_material(s, &grey, &err);
    shape_spec ball = {.kind = SHAPE_SPHERE, .radius = 1, .subdivisions = 3}, quad = {.kind = SHAPE_QUAD, .size = {40, 40}};
    mesh *m = mesh_new();
    CHECK(m && shape_build(&ball, mat, m, &err) == 0);
    for (uint32_t v = 0; v < m->nv; v++) m->pos[3 * v + 2] += 1.0f;
    scene_add_object(s, "ball", m, &err);
    m = mesh_new();
    CHECK(m && shape_build(&quad, mat, m, &err) == 0);
    scene_add_object(s, "ground", m, &err);
    CHECK(!err.msg[0]);
    return s;
}

static film *render_at(scene *s, uint32_t spp, double target, unsigned threads)
{
    s->image.spp = spp;
    s->image.noise_target = target;
    return scene_text_render_on(s, threads);
}

static int same_rgb(const film *a, const film *b)
{
    return a && b && memcmp(a->rgb, b->rgb, sizeof(float) * 3 * SIZE * SIZE) == 0;
}

/* A target no pixel reaches takes every sample; a target every pixel meets at once stops at 16.
 * A pixel whose first 16 samples agree exactly (ground in the sphere's shadow, lit by the
 * constant sky alone, before any bounce has met the sphere) does not stop on that: it failed
 * the first check before the variance's floor. */
TEST(limits_are_the_fixed_counts)
{
    scene *s = sphere_scene();
    film *all = render_at(s, 64, 0, 2), *tiny = render_at(s, 64, 1e-9, 2);
    film *first = render_at(s, 16, 0, 2), *loose = render_at(s, 64, 1.0, 2);
    CHECK(same_rgb(all, tiny));
    CHECK(!same_rgb(tiny, first));
    CHECK(same_rgb(first, loose));
    CHECK(!same_rgb(all, first));
    film_free(all), film_free(tiny), film_free(first), film_free(loose);
    scene_free(s);
}

/* At a target of 2 %: some pixels stop early (at 64 or 128 samples, 1 / target being 50) and
 * some go on (the image is neither the 64- nor the 256-sample one), one and two threads give the same bytes, and the luminance's relative
 * error against 1024 samples, over the pixels, is within 2.5 times the target (the target bounds
 * one standard error; stratification keeps the real error below the estimate). */
TEST(target_between_the_limits)
{
    scene *s = sphere_scene();
    film *a = render_at(s, 256, 0.02, 1), *b = render_at(s, 256, 0.02, 2);
    film *low = render_at(s, 64, 0, 2), *high = render_at(s, 256, 0, 2), *ref = render_at(s, 1024, 0, 2);
    CHECK(same_rgb(a, b));
    CHECK(!same_rgb(a, low));
    CHECK(!same_rgb(a, high));
    if (a && ref) {
        double e2 = 0;
        for (int i = 0; i < SIZE * SIZE; i++) {
            double la = 0.2126 * a->rgb[3 * i] + 0.7152 * a->rgb[3 * i + 1] + 0.0722 * a->rgb[3 * i + 2];
            double lr = 0.2126 * ref->rgb[3 * i] + 0.7152 * ref->rgb[3 * i + 1] + 0.0722 * ref->rgb[3 * i + 2];
            e2 += (la - lr) * (la - lr) / (lr * lr);
        }
        double rms = sqrt(e2 / (SIZE * SIZE));
        fprintf(stderr, "  relative error at a target of 0.02: %.4f\n", rms);
        CHECK(rms < 0.05);
    }
    film_free(a), film_free(b), film_free(low), film_free(high), film_free(ref);
    scene_free(s);
}

TEST_LIST(TEST_CASE(limits_are_the_fixed_counts), TEST_CASE(target_between_the_limits))
