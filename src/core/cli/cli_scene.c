/* cli_scene.c — loading and building a scene for a command. */
#include "cli/cli_scene.h"

#include <string.h>

#include "cli/cli_status.h"
#include "util/progress.h"

int cli_scene_open(cli_scene *c, const char *cmd, const char *scene_path, const char *viewpoint,
                   const build_options *opt)
{
    memset(c, 0, sizeof *c);
    err_buf err = {{0}};
    double t0 = progress_now();
    if (!(c->reg = plugin_registry_open(&err))) return cli_fail(cmd, &err, ERR_INTERNAL);
    /* Problems of the scene file speak of it themselves. */
    if (!(c->sf = scene_file_load(scene_path, c->reg, &err))) return cli_fail(NULL, &err, ERR_INPUT);
    if (viewpoint && scene_file_use_viewpoint(c->sf, viewpoint, &err)) return cli_fail(cmd, &err, ERR_USAGE);
    if (!(c->scene = scene_build(c->sf, c->reg, opt, &err))) return cli_fail(NULL, &err, ERR_INPUT);
    c->seconds = progress_now() - t0;
    return EXIT_OK;
}

void cli_scene_close(cli_scene *c)
{
    scene_free(c->scene);
    scene_file_free(c->sf);
    plugin_registry_free(c->reg);
    memset(c, 0, sizeof *c);
}
