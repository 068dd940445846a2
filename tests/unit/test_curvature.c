/* test_curvature.c — the Earth's curvature and refraction in the renderer (render/curved_ray.h):
 * a 100 m mast 20 km away drops in the image by (1 - k) d^2 / (2 R) to within a pixel (in the
 * verification mode and the path tracer alike), the chain of chords stays within its angular
 * tolerance of the curved path, and the `earth:` section reads as documented. */
#include <math.h>

#include "harness.h"
#include "scene_fixture.h"
#include "render/curved_ray.h"
#include "render/film.h"
#include "render/render.h"
#include "scene_file/scene_file.h"

#define SCENES SYLVA_TEST_DATA_DIR "/scenes"
#define MAST_SCENE SCENES "/earth/mast_20km.yaml"

/* The first row from the top whose centre ray, in column x, sees an object; -1 for none. */
static int first_object_row(const film *f, uint32_t x)
{
    for (uint32_t y = 0; y < f->height; y++)
        if (f->pixel_class[(size_t)y * f->width + x] == PIXEL_OBJECT) return (int)y;
    return -1;
}

/* The image row (continuous, 0 at the top edge) where a point at height dz above the eye and at
 * distance dist straight ahead appears, for the level pinhole camera of s. */
static double row_of(const scene *s, double dz, double dist)
{
    double tan_half_y = tan(s->camera.fov_deg * M_PI / 360.0) * s->image.height / s->image.width;
    return (1.0 - dz / dist / tan_half_y) * s->image.height / 2.0;
}

TEST(mast_drops_by_the_formula)
{
    scene *s = fixture_scene(MAST_SCENE);
    if (!s) return;
    CHECK_INT(s->earth.curvature, 1);
    CHECK_NEAR(s->earth.refraction, 0.13, 0);
    CHECK_NEAR(s->earth.radius, 6371000, 0);
    render_options ro = {.threads = 2, .verify = 1, .quiet = 1};
    err_buf err = {{0}};
    film *curved = render_scene(s, &ro, NULL, &err);
    ro.flat_earth = 1;
    film *flat = render_scene(s, &ro, NULL, &err);
    CHECK(curved && flat);
    if (curved && flat) {
        uint32_t x = s->image.width / 2;
        /* The top front edge of the box: 98 m above the eye, 19,995 m ahead. */
        double dist = 19995.0, top = 98.0;
        double drop_m = (1.0 - 0.13) * dist * dist / (2.0 * 6371000.0);
        double edge_flat = row_of(s, top, dist), edge_curved = row_of(s, top - drop_m, dist);
        int r_flat = first_object_row(flat, x), r_curved = first_object_row(curved, x);
        fprintf(stderr, "mast top: flat row %d (edge %.2f), curved row %d (edge %.2f); drop %d rows, "
                        "expected %.2f (%.2f m)\n",
                r_flat, edge_flat, r_curved, edge_curved, r_curved - r_flat, edge_curved - edge_flat, drop_m);
        /* The first row whose centre (row + 0.5) lies below the edge. */
        CHECK_NEAR(r_flat, ceil(edge_flat - 0.5), 1);
        CHECK_NEAR(r_curved, ceil(edge_curved - 0.5), 1);
        CHECK_NEAR(r_curved - r_flat, edge_curved - edge_flat, 1.0);
        CHECK(edge_curved - edge_flat > 20.0); /* the test can tell a drop from none */
        /* Depth along the view stays the distance to the mast. */
        size_t k = (size_t)(r_curved + 2) * curved->width + x;
        CHECK_NEAR(curved->depth[k], dist, 1.0);
    }
    /* The path tracer bends its camera rays alike: the same top row, and the sky (coverage 0)
     * just above it where the flat render's mast stood. */
    ro = (render_options){.threads = 2, .quiet = 1, .spp = 1};
    film *traced = render_scene(s, &ro, NULL, &err);
    CHECK(traced != NULL);
    if (traced && curved) {
        uint32_t x = s->image.width / 2;
        int r = first_object_row(traced, x);
        CHECK_INT(r, first_object_row(curved, x));
        if (r > 0) CHECK_NEAR(traced->coverage[(size_t)(r - 1) * traced->width + x], 0, 0);
    }
    film_free(traced);
    film_free(curved);
    film_free(flat);
    scene_free(s);
}

/* With refraction k = 1 the ray bends as the Earth does: the image is that of a flat Earth, bit
 * for bit. */
TEST(refraction_one_is_flat)
{
    scene *s = fixture_scene(MAST_SCENE);
    if (!s) return;
    render_options ro = {.threads = 1, .verify = 1, .quiet = 1, .width = 160, .height = 120};
    err_buf err = {{0}};
    s->earth.refraction = 1.0;
    film *a = render_scene(s, &ro, NULL, &err);
    s->earth.curvature = 0;
    film *b = render_scene(s, &ro, NULL, &err);
    CHECK(a && b);
    if (a && b) CHECK(!memcmp(a->rgb, b->rgb, sizeof(float) * 3 * a->width * a->height));
    film_free(a);
    film_free(b);
    scene_free(s);
}

/* Walks the chords of rays at several elevations and checks, at points along each chord, that
 * the angle between the chord and the curved path as seen from the camera stays within the
 * tolerance; also counts the chords out to 100 km. */
TEST(chords_stay_within_tolerance)
{
    camera c = {.origin = {0, 0, 2}, .forward = {0, 1, 0}, .right = {1, 0, 0}, .up = {0, 0, 1},
                .tan_half_x = 0.0174551f, .tan_half_y = 0.0130913f, .width = 640, .height = 480};
    earth_settings e = {.curvature = 1, .refraction = 0.13, .radius = 6371000};
    float lo[3] = {-100000, -100000, -10}, hi[3] = {100000, 100000, 3000};
    curved_rays cr;
    curved_rays_init(&cr, &e, &c, lo, hi);
    CHECK_INT(cr.on, 1);
    double lift = 0.87 / (2 * 6371000.0), worst = 0;
    uint32_t most = 0;
    for (int i = 0; i < 5; i++) {
        double el = (-0.01 + 0.005 * i); /* radians */
        vec3 d = v3(0, (float)cos(el), (float)sin(el));
        curved_path p;
        curved_path_begin(&p, &cr, d);
        vec3 org, dir;
        float len;
        double t0, dt;
        uint32_t n = 0;
        while (curved_path_next(&p, &org, &dir, &len, &t0, &dt)) {
            n++;
            CHECK(isfinite(len) && len > 0);
            for (int j = 1; j < 8; j++) {
                double u = len * j / 8.0, t = t0 + dt * j / 8.0;
                double cy = org.y + u * dir.y, cz = org.z + u * dir.z;         /* on the chord */
                double py = t * d.y, pz = 2 + t * d.z + lift * (t * d.y) * (t * d.y); /* on the path */
                double ang = fabs(atan2(cz - 2, cy) - atan2(pz - 2, py));
                if (ang > worst) worst = ang;
            }
        }
        if (n > most) most = n;
    }
    fprintf(stderr, "tolerance %.3g rad, worst chord error %.3g rad, at most %u chords to 100 km\n",
            cr.tolerance, worst, most);
    CHECK(worst <= cr.tolerance * 1.01);
    CHECK(most > 1 && most < 200);
}

/* A ray straight down needs no bending: one straight ray, as on a flat Earth. */
TEST(vertical_ray_is_straight)
{
    camera c = {.origin = {0, 0, 100}, .tan_half_x = 0.5f, .tan_half_y = 0.5f, .width = 100, .height = 100};
    earth_settings e = {.curvature = 1, .refraction = 0.13, .radius = 6371000};
    float lo[3] = {-10, -10, 0}, hi[3] = {10, 10, 1};
    curved_rays cr;
    curved_rays_init(&cr, &e, &c, lo, hi);
    curved_path p;
    curved_path_begin(&p, &cr, v3(0, 0, -1));
    vec3 org, dir;
    float len;
    double t0, dt;
    CHECK_INT(curved_path_next(&p, &org, &dir, &len, &t0, &dt), 1);
    CHECK(isinf(len));
    CHECK_INT(curved_path_next(&p, &org, &dir, &len, &t0, &dt), 0);
}

/* Without a site and without an earth: section the Earth is flat; the keys read as given. */
TEST(earth_section_defaults)
{
    err_buf err = {{0}};
    scene_file *sf = scene_file_load(SCENES "/minimal.yaml", NULL, &err);
    CHECK(sf != NULL);
    if (sf) {
        CHECK_INT(sf->earth.curvature, 0);
        CHECK_NEAR(sf->earth.refraction, 0.13, 0);
        CHECK_NEAR(sf->earth.radius, 6371000, 0);
    }
    scene_file_free(sf);
}

TEST_LIST(TEST_CASE(mast_drops_by_the_formula), TEST_CASE(refraction_one_is_flat),
          TEST_CASE(chords_stay_within_tolerance), TEST_CASE(vertical_ray_is_straight),
          TEST_CASE(earth_section_defaults))
