/* test_scene_probe.c — what scene_probe reports at a point of tests/scenes/probe_grid.yaml: the
 * terrain's height (bilinear, as plants stand on it), slope and aspect, water, the plants within
 * a radius nearest first (one standing height_above_ground over the terrain), the objects over the point; a point off the terrain and a scene
 * without terrain are refused with a sentence. */
#include <math.h>

#include "harness.h"
#include "scene_fixture.h"
#include "scene_file/scene_file.h"
#include "site/scene_probe.h"

TEST(ground_plants_and_objects)
{
    scene *s = fixture_scene(SYLVA_TEST_DATA_DIR "/scenes/probe_grid.yaml");
    if (!s) return;
    probe_result r;
    err_buf err = {{0}};
    CHECK_INT(scene_probe(s, 5, 5, 10, &r, &err), 0);
    CHECK_NEAR(r.ground, 5, 1e-9);
    CHECK_NEAR(r.slope_deg, 45, 1e-9);
    CHECK_NEAR(r.aspect_deg, 270, 1e-9); /* rising to the east, it falls toward the west */
    CHECK_INT(r.water, 0);
    CHECK_INT(r.n_plants, 2);
    if (r.n_plants == 2) {
        CHECK_NEAR(r.plants[0].distance, 1, 1e-6);
        CHECK_NEAR(r.plants[0].height, 3, 1e-6);
        CHECK_NEAR(r.plants[0].position[2], 6, 1e-6); /* on the ground at x = 6 */
        CHECK_NEAR(r.plants[1].distance, 7, 1e-6);
        CHECK_NEAR(r.plants[1].height, 2, 1e-6);
        CHECK(!strcmp(s->species[r.plants[1].species].name, "crate"));
    }
    CHECK_INT(r.n_objects, 1);
    if (r.n_objects == 1) {
        CHECK(!strcmp(s->objects[r.objects[0].object].name, "shed"));
        CHECK_NEAR(r.objects[0].top, 8, 1e-5);
    }
    probe_result_free(&r);

    /* the middle of the north-east cell: bilinear between 10, 20, 10 and 40 */
    CHECK_INT(scene_probe(s, 15, 15, 0.5, &r, &err), 0);
    CHECK_NEAR(r.ground, 20, 1e-9);
    CHECK_INT(r.n_plants, 0);
    CHECK_INT(r.n_objects, 1); /* the mast */
    probe_result_free(&r);

    /* a plant 12 m above the ground (16 m there) */
    CHECK_INT(scene_probe(s, 16, 2, 0.1, &r, &err), 0);
    CHECK_NEAR(r.ground, 16, 1e-9);
    CHECK_INT(r.n_plants, 1);
    if (r.n_plants == 1) CHECK_NEAR(r.plants[0].position[2], 28, 1e-5);
    probe_result_free(&r);

    /* water over the low western edge only */
    s->terrain->has_water = 1;
    s->terrain->water_level = 3;
    CHECK_INT(scene_probe(s, 2, 5, 1, &r, &err), 0);
    CHECK_INT(r.water, 1);
    CHECK_NEAR(r.water_depth, 1, 1e-9);
    probe_result_free(&r);
    CHECK_INT(scene_probe(s, 5, 5, 1, &r, &err), 0);
    CHECK_INT(r.water, 0);
    probe_result_free(&r);
    scene_free(s);
}

TEST(off_the_terrain)
{
    scene *s = fixture_scene(SYLVA_TEST_DATA_DIR "/scenes/probe_grid.yaml");
    if (!s) return;
    probe_result r;
    err_buf err = {{0}};
    CHECK_INT(scene_probe(s, 25, 5, 10, &r, &err), -1);
    CHECK_INT(err.status, ERR_INPUT);
    CHECK_STR_CONTAINS(err.msg, "(25.000, 5.000) lies outside the terrain, which spans x from 0.000 to 20.000");
    probe_result_free(&r);
    scene_free(s);
    s = fixture_scene(SYLVA_TEST_DATA_DIR "/scenes/minimal.yaml");
    if (!s) return;
    CHECK_INT(scene_probe(s, 0, 0, 10, &r, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "the scene has no terrain to probe");
    probe_result_free(&r);
    scene_free(s);
}

TEST_LIST(TEST_CASE(ground_plants_and_objects), TEST_CASE(off_the_terrain))
