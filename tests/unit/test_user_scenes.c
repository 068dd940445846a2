/* test_user_scenes.c — every scene file shipped in scenes/ loads and validates against the
 * built plugins' schemas, so a user can render each as it is. (Rendering them all is the job
 * of the image and cross-check tests at small sizes; here only the files themselves.) */
#include <dirent.h>

#include "harness.h"
#include "plugin/plugin_host.h"
#include "scene_file/scene_file.h"

#define SCENES SYLVA_TEST_DATA_DIR "/../scenes"

TEST(every_scene_loads)
{
    err_buf err = {{0}};
    plugin_registry *reg = plugin_registry_open(&err);
    CHECK(reg != NULL);
    if (!reg) return;
    CHECK_INT(plugin_registry_load_all(reg, &err), 0);
    CHECK(plugin_registry_count(reg) >= 5); /* terrain_ifs, three tree plugins, ecology */
    DIR *d = opendir(SCENES);
    CHECK(d != NULL);
    int loaded = 0;
    for (struct dirent *e; d && (e = readdir(d));) {
        size_t n = strlen(e->d_name);
        if (n < 6 || strcmp(e->d_name + n - 5, ".yaml")) continue;
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", SCENES, e->d_name);
        scene_file *sf = scene_file_load(path, reg, &err);
        if (!sf) fprintf(stderr, "%s\n", err.msg);
        CHECK(sf != NULL);
        loaded += sf != NULL;
        scene_file_free(sf);
    }
    if (d) closedir(d);
    fprintf(stderr, "%d scene files load\n", loaded);
    CHECK(loaded >= 30);
    plugin_registry_free(reg);
}

TEST_LIST(TEST_CASE(every_scene_loads))
