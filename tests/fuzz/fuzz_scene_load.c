/* fuzz_scene_load.c — libFuzzer target for the scene loader: each input is written to a scene
 * file in a scratch folder and read with scene_file_load() against the project's plugin
 * registry, so plugin blocks are validated against the plugins' schemas (no plugin code runs
 * beyond the descriptors). Loading must end in a scene or an error sentence: a crash, a
 * sanitizer report, a leak, a hang or runaway memory is a finding. */
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "plugin/plugin_host.h"
#include "scene/scene_file.h"
#include "work_dir.h"

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
    snprintf(path, sizeof path, "%s", work_path("scene.yaml"));
    scene_path = path;
    return 0;
}

/* Replaces the scratch scene's contents with the input; 0 on success. The file is overwritten
 * and then cut to size, not truncated first: ext4 flushes a file truncated to zero and rewritten
 * when it is closed, which would make disk writes the cost of every execution. */
static int write_scene(const uint8_t *data, size_t size)
{
    int fd = open(scene_path, O_WRONLY | O_CREAT, 0600);
    if (fd < 0) return -1;
    size_t done = 0;
    while (done < size) {
        ssize_t w = pwrite(fd, data + done, size - done, (off_t)done);
        if (w <= 0) break;
        done += (size_t)w;
    }
    int bad = done != size || ftruncate(fd, (off_t)size) != 0;
    bad |= close(fd) != 0;
    return bad ? -1 : 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (write_scene(data, size)) {
        fprintf(stderr, "fuzz_scene_load: cannot write %s\n", scene_path);
        abort();
    }
    err_buf err = {{0}};
    scene_file *sf = scene_file_load(scene_path, registry, &err);
    if (!sf && !err.msg[0]) {
        fprintf(stderr, "fuzz_scene_load: loading failed without a message\n");
        abort();
    }
    scene_file_free(sf);
    return 0;
}
