/* test_ztv_targets.c — targets given as heights above development objects stand on the objects
 * as placed: on a terrain rising 0.1 m a metre eastward, a 40 m block snapped to the lowest
 * ground under its footprint (2 m below the ground at its centre) has its target 50 m above
 * that base, the z its bottom rests at, as does every row of a layout and a group. */
#include <math.h>

#include "scene_text.h"
#include "ztv/ztv_targets.h"

#define SCENE_HEAD                                                                                      \
    "camera: {position: [0, -200, 30], look_at: [0, 0, 0]}\n"                                          \
    "terrain: {grid: [[-10, 10], [-10, 10]], origin: [-100, -100], spacing: [200, 200]}\n"

/* Loads text, builds it and its targets; the test fails when any step does. */
static int targets_of(const char *text, scene_file **sf, scene **s, ztv_targets *t)
{
    err_buf err = {{0}};
    const char *path = work_file("scene.yaml", text);
    *s = NULL;
    *sf = path ? scene_file_load(path, NULL, &err) : NULL;
    build_options bo = {.quiet = 1};
    if (*sf) *s = scene_build(*sf, NULL, &bo, &err);
    int rc = *s ? ztv_targets_build(t, *sf, *s, 1, &err) : -1;
    if (rc) fprintf(stderr, "%s\n", err.msg);
    CHECK_INT(rc, 0);
    return rc;
}

TEST(target_on_the_snapped_base)
{
    scene_file *sf;
    scene *s;
    ztv_targets t;
    if (targets_of(SCENE_HEAD "objects:\n"
                              "  - {name: block, shape: box, size: [40, 40, 10], position: [0, 0], development: true}\n"
                              "ztv: {target_heights: [50, 80]}\n",
                   &sf, &s, &t) == 0) {
        double lo[3], hi[3];
        scene_text_object_bounds(s, 0, lo, hi);
        CHECK_NEAR(s->objects[0].base, -2.0, 1e-9); /* the ground under the west edge, x = -20 */
        CHECK_NEAR(lo[2], s->objects[0].base, 1e-4);
        CHECK_INT(t.n, 2);
        CHECK_NEAR(t.p[0][0], 0, 0);
        CHECK_NEAR(t.p[0][1], 0, 0);
        CHECK_NEAR(t.p[0][2], s->objects[0].base + 50, 1e-9);
        CHECK_NEAR(t.p[1][2], s->objects[0].base + 80, 1e-9);
        ztv_targets_free(&t);
    }
    scene_free(s);
    scene_file_free(sf);
}

/* A layout of masts along the slope and a group: one target per row at its own base. */
TEST(layout_rows_and_groups_on_their_bases)
{
    CHECK(work_file("masts.csv", "id,x,y\nM1,-40,0\nM2,0,0\nM3,40,0\n") != NULL);
    scene_file *sf;
    scene *s;
    ztv_targets t;
    if (targets_of(SCENE_HEAD "groups:\n  hut:\n"
                              "    - {name: floor, shape: box, size: [10, 10, 1], position: [0, 0, 0.5]}\n"
                              "    - {name: roof, shape: box, size: [10, 10, 1], position: [0, 0, 4.5]}\n"
                              "objects:\n"
                              "  - {layout: masts.csv, shape: box, size: [4, 4, 30], development: true}\n"
                              "  - {name: hut, group: hut, position: [60, 30], development: true}\n"
                              "ztv: {target_heights: [20]}\n",
                   &sf, &s, &t) == 0) {
        CHECK_INT(t.n, 4);
        const double base[4] = {-4.2, -0.2, 3.8, 5.5}; /* the ground under each west edge */
        for (uint32_t k = 0; k < 4 && k < t.n; k++) CHECK_NEAR(t.p[k][2], base[k] + 20, 1e-6);
        ztv_targets_free(&t);
    }
    scene_free(s);
    scene_file_free(sf);
}

TEST_LIST(TEST_CASE(target_on_the_snapped_base), TEST_CASE(layout_rows_and_groups_on_their_bases))
