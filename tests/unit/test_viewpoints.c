/* test_viewpoints.c — named viewpoints beside the scene's camera (the viewpoints: section,
 * scene_file_use_viewpoint): each is read as the camera is, one of them replaces the camera before
 * the scene is built (its height above ground resolved on the terrain then), and a name the scene
 * does not have is refused with the names it has. */
#include <math.h>
#include <string.h>

#include "harness.h"
#include "work_dir.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"

static const char *scene_text =
    "image: {width: 32, height: 24, spp: 1}\n"
    "camera: {position: [0, -10, 2], look_at: [0, 0, 1]}\n"
    "viewpoints:\n"
    "  east: {position: [10, 0], height_above_ground: 1.6, heading: 270, focal_length: 50}\n"
    "  high: {position: [0, 0, 50], direction: [0, 0, -1], up: [0, 1, 0]}\n"
    "terrain: {grid: [[2, 2], [4, 4]], origin: [-20, -20], spacing: [40, 40]}\n";

static scene_file *load(err_buf *err)
{
    const char *path = work_file("viewpoints.yaml", scene_text);
    CHECK(path != NULL);
    return path ? scene_file_load(path, NULL, err) : NULL;
}

TEST(viewpoint_replaces_the_camera)
{
    err_buf err = {{0}};
    scene_file *sf = load(&err);
    if (!sf) fprintf(stderr, "%s\n", err.msg);
    CHECK(sf != NULL);
    if (!sf) return;
    CHECK_INT(sf->n_viewpoints, 2);
    CHECK_STR_CONTAINS(sf->viewpoints[1].name, "high");
    CHECK_INT(scene_file_use_viewpoint(sf, "east", &err), 0);
    scene *s = scene_build(sf, NULL, NULL, &err);
    CHECK(s != NULL);
    if (s) {
        /* ground at (10, 0): rows 2 m (south) and 4 m (north), halfway: 3 m; the eye 1.6 m above */
        CHECK_NEAR(s->camera.position[0], 10.0, 1e-12);
        CHECK_NEAR(s->camera.position[2], 3.0 + 1.6, 1e-6);
        CHECK_NEAR(s->camera.direction[0], -1.0, 1e-12); /* heading 270: due west */
        CHECK_NEAR(s->camera.direction[1], 0.0, 1e-12);
        CHECK_NEAR(s->camera.focal_length_mm, 50.0, 1e-12);
        scene_free(s);
    }
    scene_file_free(sf);
}

TEST(unknown_viewpoint_names_the_others)
{
    err_buf err = {{0}};
    scene_file *sf = load(&err);
    CHECK(sf != NULL);
    if (!sf) return;
    double before = sf->camera.position[1];
    CHECK_INT(scene_file_use_viewpoint(sf, "west", &err), -1);
    CHECK_INT(err.status, ERR_USAGE);
    CHECK_STR_CONTAINS(err.msg, "has no viewpoint 'west'; its viewpoints are: east, high");
    CHECK_NEAR(sf->camera.position[1], before, 0.0); /* the camera is left as it was */
    scene_file_free(sf);
}

TEST_LIST(TEST_CASE(viewpoint_replaces_the_camera), TEST_CASE(unknown_viewpoint_names_the_others))
