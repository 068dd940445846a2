/* scene_text.h — scene files written by a test into its work folder (work_dir.h), loaded and
 * built without plugins, rendered, a grey material added, and the world bounds of a built object;
 * or built with the project's plugins for an analysis. Header-only, for the test executables. */
#ifndef SYLVA_TEST_SCENE_TEXT_H
#define SYLVA_TEST_SCENE_TEXT_H

#include <math.h>
#include <sys/stat.h>

#include "harness.h"
#include "work_dir.h"
#include "plugin/plugin_host.h"
#include "render/film.h"
#include "render/render.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"

/* Writes text as scene.yaml in the work folder and builds it; NULL with err on failure. The
 * caller frees the scene with scene_free. */
static inline scene *scene_text_build(const char *text, err_buf *err)
{
    const char *path = work_file("scene.yaml", text);
    if (!path) {
        err_set(err, "cannot write scene.yaml in the work folder");
        return NULL;
    }
    scene_file *sf = scene_file_load(path, NULL, err);
    if (!sf) return NULL;
    scene *s = scene_build(sf, NULL, NULL, err);
    scene_file_free(sf);
    return s;
}

/* As scene_text_build; the test fails (and the message is printed) when it does not build. */
static inline scene *scene_text_build_ok(const char *text)
{
    err_buf err = {{0}};
    scene *s = scene_text_build(text, &err);
    if (!s) fprintf(stderr, "%s\n", err.msg);
    CHECK(s != NULL);
    return s;
}

/* Renders s at its own settings on `threads` threads; the test fails (and the message is
 * printed) when it cannot. The caller frees the film with film_free. */
static inline film *scene_text_render_on(const scene *s, unsigned threads)
{
    render_options ro = {.threads = threads, .quiet = 1};
    err_buf err = {{0}};
    film *f = render_scene(s, &ro, NULL, &err);
    if (!f) fprintf(stderr, "%s\n", err.msg);
    CHECK(f != NULL);
    return f;
}

/* As scene_text_render_on, on two threads. */
static inline film *scene_text_render(const scene *s) { return scene_text_render_on(s, 2); }

/* Adds a grey Lambertian material to s; its id. */
static inline int32_t scene_text_lambert(scene *s, const char *name, double albedo)
{
    err_buf err = {{0}};
    sylva_material_desc m = {.size = sizeof m, .name = name, .bsdf = SYLVA_BSDF_LAMBERT,
                             .albedo = {(float)albedo, (float)albedo, (float)albedo}, .texture = -1};
    int32_t id = scene_add_material(s, &m, &err);
    CHECK(!err.msg[0]);
    return id;
}

/* The world bounds of object o's vertices. */
static inline void scene_text_object_bounds(const scene *s, uint32_t o, double lo[3], double hi[3])
{
    const xform3x4 *xf;
    const mesh *m = scene_object_mesh(s, o, &xf);
    for (int d = 0; d < 3; d++) lo[d] = INFINITY, hi[d] = -INFINITY;
    for (uint32_t v = 0; v < m->nv; v++) {
        vec3 p = v3(m->pos[v * 3], m->pos[v * 3 + 1], m->pos[v * 3 + 2]);
        if (xf) p = xf_point(xf, p);
        double q[3] = {p.x, p.y, p.z};
        for (int d = 0; d < 3; d++) lo[d] = fmin(lo[d], q[d]), hi[d] = fmax(hi[d], q[d]);
    }
}

/* 1 when the file at path exists (the shared data set's cases skip without it). */
static inline int scene_text_file_exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

/* The scene of `text` (written as NAME in the work folder), built for an analysis with the
 * project's plugins (quiet: without the loader's and the build's lines), or NULL with err set.
 * The caller frees it with scene_free. */
static inline scene *scene_text_build_analysis(const char *name, const char *text, int quiet, err_buf *err)
{
    const char *path = work_file(name, text);
    plugin_registry *reg = plugin_registry_open(err);
    unsigned flags = SCENE_FILE_NO_CAMERA | (quiet ? SCENE_FILE_QUIET : 0);
    scene_file *sf = reg && path ? scene_file_load_with(path, reg, flags, err) : NULL;
    build_options opt = {.analysis = 1, .quiet = quiet};
    scene *s = sf ? scene_build(sf, reg, &opt, err) : NULL;
    scene_file_free(sf);
    plugin_registry_free(reg);
    return s;
}

#endif
