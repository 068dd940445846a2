/* test_ground_cover_place.c — the ground cover near the camera: its density by the ground's
 * kinds and slope, placement that is the same in every run and follows the density (none on snow
 * or water, plenty on meadow; none where the scene's snow lies), only in view and within the
 * radius, and a count kept to max_instances. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "geometry/ground_cover_place.h"
#include "scene/heightfield.h"

/* A 201 x 201 m terrain, 1 m between nodes, centred on the origin, with the ground rules of a
 * terrain plugin: meadow at 1 m for x < 0, snow on a plateau 30 m high (over the 20 m snow line)
 * for x >= 0, and water (below the water level at z = 0.5) for y > 60. The camera stands 1.6 m
 * above the meadow at the origin looking north and a little down. */
static scene *split_scene(void)
{
    scene *s = scene_new();
    sylva_heightfield *hf = calloc(1, sizeof *hf);
    const uint32_t n = 201;
    float *z = malloc((size_t)n * n * sizeof *z);
    if (!s || !hf || !z) {
        scene_free(s), free(hf), free(z);
        return NULL;
    }
    *hf = (sylva_heightfield){.size = sizeof *hf, .nx = n, .ny = n, .x0 = -100, .y0 = -100, .dx = 1, .dy = 1,
                              .z = z, .has_water = 1, .water_level = 0.5, .water_material = -1,
                              .has_ground_rules = 1,
                              .ground = {.snow_z = 20, .scree_z = HUGE_VAL, .scree_slope = 60, .rock_slope = 75,
                                         .dry_humidity = 0, .grass_albedo = {0.07, 0.1, 0.04},
                                         .dry_grass_albedo = {0.2, 0.18, 0.1}, .scree_albedo = {0.3, 0.3, 0.3},
                                         .rock_albedo = {0.25, 0.25, 0.25}, .snow_albedo = {0.9, 0.9, 0.9}}};
    for (uint32_t j = 0; j < n; j++)
        for (uint32_t i = 0; i < n; i++) z[(size_t)j * n + i] = j > 160 ? 0.0f : i < 100 ? 1.0f : 30.0f;
    s->terrain = hf;
    s->image.seed = 7;
    s->camera = (camera_settings){.position = {0, 0, 2.6}, .direction = {0, 0.97014, -0.24254}, .up = {0, 0, 1},
                                  .fov_deg = 60};
    return s;
}

static const ground_cover_settings cover = {.enabled = 1, .density = 10, .radius = 0, .max_instances = 200000};

TEST(density_by_kind_and_slope)
{
    const double flat[3] = {0, 0, 1}, steep[3] = {0.866, 0, 0.5}; /* 60 degrees */
    float w[GROUND_KINDS] = {0};
    w[GROUND_MEADOW] = 1;
    double meadow = ground_cover_density(w, flat);
    CHECK_NEAR(meadow, 1, 0);
    CHECK_NEAR(ground_cover_density(w, steep), 0, 0);
    memset(w, 0, sizeof w), w[GROUND_FOREST_FLOOR] = 1;
    double forest = ground_cover_density(w, flat);
    CHECK(forest > 0 && forest < meadow);
    const ground_kind bare[] = {GROUND_ROCK, GROUND_SNOW, GROUND_WATER};
    for (size_t k = 0; k < 3; k++) {
        memset(w, 0, sizeof w), w[bare[k]] = 1;
        CHECK_NEAR(ground_cover_density(w, flat), 0, 0);
    }
    memset(w, 0, sizeof w); /* nothing known: nothing grows */
    CHECK_NEAR(ground_cover_density(w, flat), 0, 0);
}

/* Where each tuft stands, relative to the eye. */
TEST(placement_follows_the_ground)
{
    scene *a = split_scene(), *b = split_scene();
    CHECK(a && b);
    if (!a || !b) goto done;
    err_buf err = {{0}};
    ground_cover_report ra, rb;
    CHECK_INT(ground_cover_add(a, &cover, 320, 180, 0, &ra, &err), 0);
    CHECK_INT(ground_cover_add(b, &cover, 320, 180, 1, &rb, &err), 0);
    /* the same tufts, to the bit, on one thread as on one per processor */
    CHECK(ra.instances > 1000);
    CHECK_INT(ra.instances, rb.instances);
    CHECK_INT(a->n_instances, b->n_instances);
    CHECK(!memcmp(a->instances, b->instances, a->n_instances * sizeof *a->instances));
    /* the pixel radius: 320 / (2 tan 30 deg) pixels of focal length times a 0.3 m blade */
    CHECK_NEAR(ra.pixel_radius, 160.0 / tan(M_PI / 6) * 0.3, 1e-9);
    uint32_t meadow = 0, snow = 0, water = 0, behind = 0, beyond = 0;
    for (uint32_t i = 0; i < a->n_instances; i++) {
        const float *t = &a->instances[i].xf.m[0][0];
        double x = t[3], y = a->instances[i].xf.m[1][3];
        if (y > 61) water++;
        else if (x >= 0.5) snow++;
        else if (x < -0.5) meadow++;
        if (y < -1) behind++;
        if (hypot(x, y) > ra.radius) beyond++;
    }
    CHECK(meadow > 1000);
    CHECK_INT(snow, 0);
    CHECK_INT(water, 0);
    CHECK_INT(behind, 0);
    CHECK_INT(beyond, 0);
    /* the cover's own species and prototypes came with it */
    CHECK_INT(a->n_species, 2);
    CHECK(!strcmp(a->species[0].name, "ground cover grass"));
done:
    scene_free(a), scene_free(b);
}

/* Lying snow (snow:) buries the meadow's tufts where it lies: all under a closed cover (but on a
 * cliff), about half under a cover of one half, the same ones on every run. */
TEST(no_tufts_where_snow_lies)
{
    scene *open = split_scene(), *closed = split_scene(), *half = split_scene(), *again = split_scene();
    CHECK(open && closed && half && again);
    if (!open || !closed || !half || !again) goto done;
    closed->snow = (snow_settings){1, 1, -HUGE_VAL};
    half->snow = again->snow = (snow_settings){1, 0.5, -HUGE_VAL};
    err_buf err = {{0}};
    ground_cover_report r_open, r_closed, r_half, r_again;
    CHECK_INT(ground_cover_add(open, &cover, 320, 180, 0, &r_open, &err), 0);
    CHECK_INT(ground_cover_add(closed, &cover, 320, 180, 0, &r_closed, &err), 0);
    CHECK_INT(ground_cover_add(half, &cover, 320, 180, 0, &r_half, &err), 0);
    CHECK_INT(ground_cover_add(again, &cover, 320, 180, 0, &r_again, &err), 0);
    fprintf(stderr, "tufts: %u without snow, %u under a closed cover, %u under half a cover\n", r_open.instances,
            r_closed.instances, r_half.instances);
    CHECK(r_open.instances > 1000);
    /* none under a closed cover but on the plateau's cliff, where the snow slides off */
    uint32_t off_the_cliff = 0;
    for (uint32_t i = 0; i < closed->n_instances; i++) off_the_cliff += fabsf(closed->instances[i].xf.m[0][3]) > 3;
    CHECK(r_closed.instances < 50);
    CHECK_INT(off_the_cliff, 0);
    CHECK(r_half.instances > 0.3 * r_open.instances && r_half.instances < 0.7 * r_open.instances);
    CHECK_INT(r_again.instances, r_half.instances);
    CHECK(half->n_instances == again->n_instances &&
          !memcmp(half->instances, again->instances, half->n_instances * sizeof *half->instances));
done:
    scene_free(open), scene_free(closed), scene_free(half), scene_free(again);
}

TEST(count_kept_to_the_cap)
{
    scene *s = split_scene(), *off = split_scene();
    CHECK(s && off);
    if (!s || !off) goto done;
    err_buf err = {{0}};
    ground_cover_settings capped = cover;
    capped.max_instances = 500;
    ground_cover_report rep;
    CHECK_INT(ground_cover_add(s, &capped, 320, 180, 0, &rep, &err), 0);
    CHECK(rep.instances > 0 && rep.instances <= 500);
    CHECK_INT(rep.capped, 1);
    CHECK(rep.radius < rep.pixel_radius);
    ground_cover_settings disabled = cover;
    disabled.enabled = 0;
    CHECK_INT(ground_cover_add(off, &disabled, 320, 180, 0, &rep, &err), 0);
    CHECK_INT(rep.instances, 0);
    CHECK_INT(off->n_instances, 0);
    CHECK_INT(off->n_species, 0);
done:
    scene_free(s), scene_free(off);
}

/* Tufts stand on the drawn surface: where a level of detail covers a point, that level's
 * triangles (they were placed on the coarse grid's, buried or floating where the two differ). */
TEST(surface_height_on_the_finest_level)
{
    float base[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0}; /* 3 x 3 nodes, 10 m apart, flat at 0 */
    float fine[25];
    for (int k = 0; k < 25; k++) fine[k] = 1.0f; /* cell (0, 0) refined 4 times, 1 m higher */
    sylva_terrain_level lv = {.size = sizeof lv, .i0 = 0, .j0 = 0, .cells_x = 1, .cells_y = 1, .refine = 4,
                              .nx = 5, .ny = 5, .z = fine};
    sylva_heightfield hf = {.size = sizeof hf, .nx = 3, .ny = 3, .dx = 10, .dy = 10, .z = base, .water_material = -1,
                            .n_levels = 1, .levels = &lv};
    double z = -9;
    CHECK_INT(heightfield_surface_height(&hf, 4.0, 6.0, &z), 0);
    CHECK_NEAR(z, 1.0, 1e-9);
    CHECK_INT(heightfield_surface_height(&hf, 15.0, 15.0, &z), 0); /* outside the level */
    CHECK_NEAR(z, 0.0, 1e-9);
}

TEST_LIST(TEST_CASE(surface_height_on_the_finest_level), TEST_CASE(no_tufts_where_snow_lies), TEST_CASE(density_by_kind_and_slope), TEST_CASE(placement_follows_the_ground),
          TEST_CASE(count_kept_to_the_cap))
