/* scene_fixture.h — a test's scene built from a scene file, as a command builds it (no plugins):
 * a failure to load or build fails the running test with the loader's sentence. Header-only, for
 * the test executables (after harness.h). */
#ifndef SYLVA_TEST_SCENE_FIXTURE_H
#define SYLVA_TEST_SCENE_FIXTURE_H

#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"

/* A new scene (caller frees with scene_free), or NULL after a failed CHECK. */
static inline scene *fixture_scene(const char *path)
{
    err_buf err = {{0}};
    scene_file *sf = scene_file_load(path, NULL, &err);
    if (!sf) fprintf(stderr, "%s\n", err.msg);
    CHECK(sf != NULL);
    if (!sf) return NULL;
    build_options bo = {.quiet = 1};
    scene *s = scene_build(sf, NULL, &bo, &err);
    if (!s) fprintf(stderr, "%s\n", err.msg);
    CHECK(s != NULL);
    scene_file_free(sf);
    return s;
}

#endif
