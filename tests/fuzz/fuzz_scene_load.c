/* fuzz_scene_load.c — libFuzzer target for the scene loader: each input is written to a scene
 * file in a scratch folder and read with scene_file_load() against the project's plugin
 * registry, so plugin blocks are validated against the plugins' schemas (no plugin code runs
 * beyond the descriptors). Loading must end in a scene or an error sentence: a crash, a
 * sanitizer report, a leak, a hang or runaway memory is a finding. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "plugin/plugin_host.h"
#include "scene_file/scene_file.h"
#include "fuzz_file.h"

static plugin_registry *registry;  /* opened once, freed at exit */
static const char *scene_path;     /* the scratch scene file (work_dir.h owns it) */

static void close_registry(void) { plugin_registry_free(registry); }

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    err_buf err = {{0}};
    /* Every module opened once here, so each input sees every plugin's schema the same way. */
    registry = plugin_registry_open(&err);
    if (registry && plugin_registry_load_all(registry, &err)) {
        plugin_registry_free(registry);
        registry = NULL;
    }
    if (!registry || plugin_registry_count(registry) == 0) {
        fprintf(stderr, "fuzz_scene_load: no plugins found (%s); build the plugins first\n", err.msg);
        exit(2);
    }
    atexit(close_registry);
    static char path[1200];
    scene_path = fuzz_scratch_path("scene.yaml", path, sizeof path);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_write_file("fuzz_scene_load", scene_path, data, size);
    err_buf err = {{0}};
    scene_file *sf = scene_file_load(scene_path, registry, &err);
    if (!sf && !err.msg[0]) fuzz_finding("fuzz_scene_load", "loading failed without a message");
    scene_file_free(sf);
    return 0;
}
