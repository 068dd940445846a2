/* plugin_module.h — a registry holding one plugin module of the build (build/plugins/NAME.so)
 * and nothing else, and a scene file loaded and built with it as a command does, for the tests
 * that drive a plugin through the real host. Header-only, for the test executables. */
#ifndef SYLVA_TEST_PLUGIN_MODULE_H
#define SYLVA_TEST_PLUGIN_MODULE_H

#include <stdio.h>

#include "plugin/plugin_host.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"

/* The registry of module `file` (a path; caller frees with plugin_registry_free), or NULL after
 * printing why. */
static inline plugin_registry *plugin_module_registry(const char *file)
{
    err_buf err = {{0}};
    plugin_registry *reg = plugin_registry_open_path("", &err);
    if (reg && plugin_registry_add_file(reg, file, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        plugin_registry_free(reg);
        return NULL;
    }
    return reg;
}

/* The scene file at path loaded and built with reg, quietly. Returns the scene (caller frees with
 * scene_free), or NULL with err set. */
static inline scene *plugin_module_scene(const plugin_registry *reg, const char *path, err_buf *err)
{
    scene *s = NULL;
    scene_file *sf = scene_file_load(path, reg, err);
    if (sf) {
        build_options opt = {.quiet = 1};
        s = scene_build(sf, reg, &opt, err);
    }
    scene_file_free(sf);
    return s;
}

#endif
