/* test_verify_mode.c — the verification mode takes POV-Ray's samples (pixel centre plus a
 * regular R x R grid, equally weighted, no jitter) and fills the coverage and class layers the
 * cross-check compares: one pixel looking straight down on a quad whose edge crosses the pixel
 * at 60 % of its width; and shades a triangle whose three normals are one vector by its
 * geometric normal, as POV-Ray does. */
#include <math.h>

#include "harness.h"
#include "render/film.h"
#include "render/render.h"
#include "scene_build/shapes.h"

#define HALF_WIDTH 0.2 /* of the pixel's footprint on the ground, metres */
#define EDGE 0.6       /* share of the pixel's width the quad covers, from the left */

static scene *edge_scene(void)
{
    scene *s = scene_new();
    err_buf err = {{0}};
    double fov = 2 * atan(HALF_WIDTH / 10.0) * 180 / M_PI;
    s->image = (image_settings){.width = 1, .height = 1, .spp = 1, .max_depth = 1};
    s->camera = (camera_settings){.position = {0, 0, 10}, .direction = {0, 0, -1}, .up = {0, 1, 0}, .fov_deg = fov};
    s->sun = (sun_settings){.enabled = 0, .direction = {0, 0, 1}};
    s->sky = (sky_settings){.model = SKY_CONSTANT, .scale = 1, .color = {0.5, 0.5, 0.5}, .ambient = {1, 1, 1}};
    sylva_material_desc white = {.size = sizeof white, .name = "white", .bsdf = SYLVA_BSDF_LAMBERT,
                                 .albedo = {1, 1, 1}, .texture = -1};
    int32_t mat = scene_add_material(s, &white, &err);
    /* a quad from x = -5 to the edge, y from -5 to 5, at z = 0 */
    double xe = -HALF_WIDTH + EDGE * 2 * HALF_WIDTH;
    float pos[12] = {-5, -5, 0, (float)xe, -5, 0, (float)xe, 5, 0, -5, 5, 0};
    uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
    mesh *m = mesh_new();
    mesh_append(m, pos, NULL, NULL, 4, tri, NULL, mat, 2, &err);
    scene_add_object(s, "half", m, &err);
    CHECK(!err.msg[0]);
    return s;
}

/* Coverage and colour of the one pixel at spp; the sky shows 0.5, the quad 1 (albedo x ambient). */
static void check_pixel(scene *s, uint32_t spp, double covered)
{
    render_options ro = {.threads = 1, .verify = 1, .quiet = 1, .spp = spp};
    err_buf err = {{0}};
    film *f = render_scene(s, &ro, NULL, &err);
    CHECK(f != NULL);
    if (!f) return;
    CHECK_NEAR(f->coverage[0], covered, 1e-6);
    CHECK_NEAR(f->rgb[0], covered * 1.0 + (1 - covered) * 0.5, 1e-6);
    CHECK_INT(f->pixel_class[0], PIXEL_OBJECT); /* the centre ray (x = 0.5 < 0.6) hits the quad */
    film_free(f);
}

TEST(samples_are_povray_method_1)
{
    scene *s = edge_scene();
    check_pixel(s, 1, 1.0);        /* the centre alone */
    check_pixel(s, 3, 1.0);        /* below 4 spp: still the centre alone */
    check_pixel(s, 4, 3.0 / 5.0);  /* centre + columns at 0.25 and 0.75: 1 + 2 of 5 */
    check_pixel(s, 8, 3.0 / 5.0);  /* rounded down to 2 x 2 */
    check_pixel(s, 9, 7.0 / 10.0); /* centre + columns at 1/6, 1/2, 5/6: 1 + 6 of 10 */
    check_pixel(s, 16, 9.0 / 17.0); /* columns at 1/8, 3/8 (5/8 misses): 1 + 8 of 17 */
    scene_free(s);
}

TEST(sky_pixel_class)
{
    scene *s = edge_scene();
    s->objects[0].mesh->nt = 0; /* nothing to hit */
    render_options ro = {.threads = 1, .verify = 1, .quiet = 1, .spp = 4};
    err_buf err = {{0}};
    film *f = render_scene(s, &ro, NULL, &err);
    CHECK(f != NULL);
    if (f) {
        CHECK_NEAR(f->coverage[0], 0.0, 0);
        CHECK_INT(f->pixel_class[0], PIXEL_SKY);
        CHECK_NEAR(f->rgb[1], 0.5, 1e-6);
    }
    film_free(f);
    scene_free(s);
}

/* A triangle whose three normals are one vector is shaded by its geometric normal, as POV-Ray
 * shades a mesh2 triangle with three equal normals: a quad tilted 30 degrees about y with its
 * normals straight up, under a sun straight overhead, gets cos 30 (not 1) of the sun; with
 * normals that differ it keeps the interpolated one. */
TEST(one_normal_is_the_geometric_one)
{
    for (int differ = 0; differ < 2; differ++) {
        scene *s = edge_scene();
        mesh *m = s->objects[0].mesh;
        double t = 30 * M_PI / 180;
        for (uint32_t v = 0; v < m->nv; v++) {
            m->pos[v * 3 + 2] = (float)(tan(t) * m->pos[v * 3]); /* z = x tan 30 */
            m->nrm[v * 3] = 0, m->nrm[v * 3 + 1] = 0, m->nrm[v * 3 + 2] = 1;
        }
        if (differ) m->nrm[0] = 1e-3f; /* one corner's normal slightly off: smooth again */
        s->sun = (sun_settings){.enabled = 1, .direction = {0, 0, 1}, .irradiance = 1, .color = {1, 1, 1}};
        s->sky.ambient[0] = s->sky.ambient[1] = s->sky.ambient[2] = 0;
        render_options ro = {.threads = 1, .verify = 1, .quiet = 1, .spp = 1};
        err_buf err = {{0}};
        film *f = render_scene(s, &ro, NULL, &err);
        CHECK(f != NULL);
        if (f) CHECK_NEAR(f->rgb[0], differ ? 1.0 : cos(t), 2e-3);
        film_free(f);
        scene_free(s);
    }
}

TEST_LIST(TEST_CASE(samples_are_povray_method_1), TEST_CASE(sky_pixel_class),
          TEST_CASE(one_normal_is_the_geometric_one))
