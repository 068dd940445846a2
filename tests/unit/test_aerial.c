/* test_aerial.c — aerial perspective in the path tracer (render/aerial.h), rendered in-process:
 * Koschmieder's law for a black target, the horizon sky it fades into, an atmosphere of zero
 * density rendering exactly as no atmosphere, the furnace test with the atmosphere off, a
 * visibility beyond clean air refused, and the verification mode's fog. */
#include <math.h>

#include "geometry/light_summary.h"
#include "harness.h"
#include "render/film.h"
#include "render/render.h"
#include "scene_build/shapes.h"

#define CAMERA_Z 100.0 /* metres above sea level (no site: z is the altitude) */
#define VISIBILITY 30.0 /* km: the scenes' temperate summer day */

/* A flat-Earth scene (curvature off, no site) with a camera at CAMERA_Z looking due north along
 * the horizontal, a 3 x 3 image 0.003 degrees across (so every sample's ray stays within a metre
 * of the horizontal at 20 km: the air along it is the camera's air), the sun in the east at
 * 35 degrees and the physical sky. With distance > 0 a black quad (albedo 0) 200 m wide faces
 * the camera at that distance, centred on the view. */
static scene *target_scene(double distance)
{
    scene *s = scene_new();
    err_buf err = {{0}};
    s->image = (image_settings){.width = 3, .height = 3, .spp = 4, .max_depth = 2, .seed = 1};
    s->camera = (camera_settings){.position = {0, 0, CAMERA_Z}, .direction = {0, 1, 0}, .up = {0, 0, 1},
                                  .fov_deg = 0.003};
    s->sun = (sun_settings){.enabled = 1, .direction = {cos(35 * M_PI / 180), 0, sin(35 * M_PI / 180)},
                            .irradiance = 1, .color = {1, 1, 1}, .angular_diameter_deg = 0.53};
    s->sky = (sky_settings){.model = SKY_PHYSICAL, .visibility_km = VISIBILITY, .density = 1, .scale = 1,
                            .ground_albedo = 0.2, .ambient = {0.2, 0.2, 0.2}};
    if (distance > 0) {
        sylva_material_desc black = {.size = sizeof black, .name = "black", .bsdf = SYLVA_BSDF_LAMBERT,
                                     .albedo = {0, 0, 0}, .texture = -1};
        int32_t mat = scene_add_material(s, &black, &err);
        float y = (float)distance, h = 100.0f, z = (float)CAMERA_Z;
        float pos[12] = {-h, y, z - h, h, y, z - h, h, y, z + h, -h, y, z + h};
        uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
        mesh *m = mesh_new();
        mesh_append(m, pos, NULL, NULL, 4, tri, NULL, mat, 2, &err);
        scene_add_object(s, "target", m, &err);
    }
    CHECK(!err.msg[0]);
    return s;
}

/* The centre pixel's RGB (and whether its centre ray met the target). */
static void centre_pixel(double distance, double rgb[3], int *hit)
{
    scene *s = target_scene(distance);
    render_options ro = {.threads = 1, .quiet = 1};
    err_buf err = {{0}};
    film *f = render_scene(s, &ro, NULL, &err);
    CHECK(f != NULL);
    rgb[0] = rgb[1] = rgb[2] = 0;
    *hit = 0;
    if (f) {
        for (int k = 0; k < 3; k++) rgb[k] = f->rgb[3 * 4 + k];
        *hit = f->pixel_class[4] != PIXEL_SKY;
        film_free(f);
    }
    scene_free(s);
}

/* Koschmieder (1924): a black target at distance d seen against the horizon sky L_h through
 * homogeneous air of extinction beta shows L(d) = L_h (1 - exp(-beta d)), so its contrast
 * (L_h - L) / L_h is exp(-beta d) = exp(-3.912 d / V). The horizon sky of that law is the light
 * of an unbounded horizontal line of sight through the camera's air: here a black target
 * 3,000 km away (optical depth 390). The camera-ray quadrature is deterministic, so the pixels
 * carry no noise and 2 % (of the contrast) is a real bound. The model's own horizon sky (a camera
 * ray that misses) comes from the spherical atmosphere, whose horizontal ray climbs out of the
 * haze; it is checked separately to lie within 1 % of that limit. */
TEST(koschmieder_contrast_of_a_black_target)
{
    double far[3], sky[3];
    int hit;
    centre_pixel(3.0e6, far, &hit);
    CHECK(hit);
    centre_pixel(0, sky, &hit);
    CHECK(!hit);
    const double d_km[3] = {1, 5, 20};
    for (int i = 0; i < 3; i++) {
        double L[3];
        centre_pixel(d_km[i] * 1000.0, L, &hit);
        CHECK(hit);
        double want = exp(-3.912 * d_km[i] / VISIBILITY);
        double contrast = (far[1] - L[1]) / far[1]; /* green: 550 nm, where V is defined */
        fprintf(stderr, "  d = %2.0f km: contrast %.5f, Koschmieder %.5f (%+.3f %%)\n", d_km[i], contrast, want,
                100.0 * (contrast / want - 1.0));
        CHECK_NEAR(contrast / want, 1.0, 0.02);
    }
    fprintf(stderr, "  horizon sky / horizontal limit: %.5f %.5f %.5f\n", sky[0] / far[0], sky[1] / far[1],
            sky[2] / far[2]);
    for (int k = 0; k < 3; k++) CHECK_NEAR(sky[k] / far[k], 1.0, 0.01);
}

/* The verification mode's fog (POV-Ray's constant fog): the black target 5 km off shows
 * (1 - exp(-5000 / D)) C with D = V / 3.912 and C the horizon's mean colour; the sky shows C. */
TEST(verification_fog)
{
    for (int target = 0; target < 2; target++) {
        scene *s = target_scene(target ? 5000 : 0);
        render_options ro = {.threads = 1, .quiet = 1, .verify = 1};
        err_buf err = {{0}};
        film *f = render_scene(s, &ro, NULL, &err);
        static light_summary l; /* its tables are large for the stack */
        CHECK_INT(light_summary_init(&l, &s->sun, &s->sky, 0, CAMERA_Z, 0, &err), 0);
        CHECK_NEAR(l.fog_distance, VISIBILITY * 1000 / 3.912, 1e-6);
        CHECK(f != NULL);
        if (f) {
            double keep = target ? exp(-5000 / l.fog_distance) : 0.0;
            CHECK_NEAR(f->rgb[3 * 4 + 0], (1 - keep) * l.fog_color.x, 1e-5);
            CHECK_NEAR(f->rgb[3 * 4 + 2], (1 - keep) * l.fog_color.z, 1e-5);
            CHECK(l.fog_color.z > l.fog_color.x); /* the horizon of a clear day: bluish */
        }
        film_free(f);
        scene_free(s);
    }
}

/* A scene with ground, a sphere and the sun, rendered with the physical sky at density 0 (and a
 * black ground below the horizon) and with no sky at all: bit for bit the same picture. */
static film *sphere_render(sky_model model, double density)
{
    scene *s = scene_new();
    err_buf err = {{0}};
    s->image = (image_settings){.width = 24, .height = 16, .spp = 4, .max_depth = 4, .seed = 3};
    s->camera = (camera_settings){.position = {0, -6, 2.5}, .look_at = {0, 0, 0.8}, .has_look_at = 1,
                                  .up = {0, 0, 1}, .fov_deg = 50};
    s->sun = (sun_settings){.enabled = 1, .direction = {-0.5, -0.5, 0.7}, .irradiance = 1, .color = {1, 1, 1},
                            .angular_diameter_deg = 0.53};
    s->sky = (sky_settings){.model = model, .visibility_km = 20, .density = density, .scale = 1,
                            .ground_albedo = 0, .ambient = {0.2, 0.2, 0.2}};
    sylva_material_desc red = {.size = sizeof red, .name = "red", .bsdf = SYLVA_BSDF_LAMBERT,
                               .albedo = {0.7, 0.12, 0.08}, .texture = -1};
    int32_t mat = scene_add_material(s, &red, &err);
    float pos[12] = {-400, -400, 0, 400, -400, 0, 400, 400, 0, -400, 400, 0};
    uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
    mesh *m = mesh_new();
    mesh_append(m, pos, NULL, NULL, 4, tri, NULL, mat, 2, &err);
    scene_add_object(s, "floor", m, &err);
    float box[24] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0, -1, -1, 2, 1, -1, 2, 1, 1, 2, -1, 1, 2};
    uint32_t faces[36] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                          1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
    m = mesh_new();
    mesh_append(m, box, NULL, NULL, 8, faces, NULL, mat, 12, &err);
    scene_add_object(s, "block", m, &err);
    CHECK(!err.msg[0]);
    render_options ro = {.threads = 1, .quiet = 1};
    film *f = render_scene(s, &ro, NULL, &err);
    CHECK(f != NULL);
    scene_free(s);
    return f;
}

TEST(zero_density_is_no_atmosphere)
{
    film *air = sphere_render(SKY_PHYSICAL, 0), *none = sphere_render(SKY_NONE, 1);
    CHECK(air && none);
    if (air && none) {
        size_t n = (size_t)air->width * air->height * 3, differ = 0;
        double lit = 0;
        for (size_t i = 0; i < n; i++) {
            differ += air->rgb[i] != none->rgb[i];
            lit += none->rgb[i];
        }
        CHECK_INT(differ, 0);
        CHECK(lit > 0); /* the sun lights the scene: the comparison is not of two black pictures */
    }
    film_free(air);
    film_free(none);
    /* and at density 1 the same scene is different (the test can tell) */
    film *thick = sphere_render(SKY_PHYSICAL, 1), *none2 = sphere_render(SKY_NONE, 1);
    if (thick && none2) CHECK(thick->rgb[0] != none2->rgb[0]);
    film_free(thick);
    film_free(none2);
}

/* The furnace: a convex object of albedo a alone under a constant sky of radiance 1 (no sun, no
 * atmosphere) reflects exactly a. The cube is the box shape, whose faces have their own flat
 * normals (a cube of eight shared corners has normals averaged across its edges, and a shading
 * normal off the face's reflects 0.8 % less). 256 spp over 256 pixels of one face (standard
 * error about 0.1 %); the mean must lie within 0.5 %. Measured: 0.50000. */
TEST(furnace_without_atmosphere)
{
    scene *s = scene_new();
    err_buf err = {{0}};
    s->image = (image_settings){.width = 16, .height = 16, .spp = 256, .max_depth = 8, .seed = 5};
    s->camera = (camera_settings){.position = {0, -10, 0}, .direction = {0, 1, 0}, .up = {0, 0, 1}, .fov_deg = 6};
    s->sun = (sun_settings){.enabled = 0, .direction = {0, 0, 1}};
    s->sky = (sky_settings){.model = SKY_CONSTANT, .scale = 1, .color = {1, 1, 1}, .ambient = {0.2, 0.2, 0.2}};
    sylva_material_desc grey = {.size = sizeof grey, .name = "grey", .bsdf = SYLVA_BSDF_LAMBERT,
                                .albedo = {0.5, 0.5, 0.5}, .texture = -1};
    int32_t mat = scene_add_material(s, &grey, &err);
    shape_spec box = {.kind = SHAPE_BOX, .size = {6, 6, 6}};
    mesh *m = mesh_new();
    CHECK(m && shape_build(&box, mat, m, &err) == 0);
    scene_add_object(s, "cube", m, &err);
    render_options ro = {.threads = 1, .quiet = 1};
    film *f = render_scene(s, &ro, NULL, &err);
    CHECK(f != NULL);
    if (f) {
        double sum = 0;
        int n = 0;
        for (int i = 0; i < 256; i++)
            if (f->coverage[i] == 1.0f) {
                sum += f->rgb[3 * i + 1];
                n++;
            }
        CHECK(n > 100);
        fprintf(stderr, "  furnace: %.5f over %d pixels (albedo 0.5)\n", sum / n, n);
        CHECK_NEAR(sum / n, 0.5, 0.0025);
    }
    film_free(f);
    scene_free(s);
}

/* A visibility longer than clean air gives at the camera is the scene's fault (exit status 2),
 * said with the limit; the same visibility from 5 km up is valid (thinner air: 541 km there). */
TEST(visibility_beyond_clean_air)
{
    scene *s = target_scene(0);
    s->sky.visibility_km = 500;
    render_options ro = {.threads = 1, .quiet = 1};
    err_buf err = {{0}};
    film *f = render_scene(s, &ro, NULL, &err);
    CHECK(f == NULL);
    CHECK_INT(err.status, ERR_INPUT);
    CHECK_STR_CONTAINS(err.msg, "visibility 500 km is longer than clean air allows at the camera's altitude of 100 m");
    film_free(f);
    s->camera.position[2] = 5000;
    err = (err_buf){{0}};
    f = render_scene(s, &ro, NULL, &err);
    CHECK(f != NULL);
    film_free(f);
    scene_free(s);
}

TEST_LIST(TEST_CASE(koschmieder_contrast_of_a_black_target), TEST_CASE(zero_density_is_no_atmosphere),
          TEST_CASE(furnace_without_atmosphere), TEST_CASE(visibility_beyond_clean_air), TEST_CASE(verification_fog))
