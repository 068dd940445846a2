/* cli_scene.c — loading, building and preparing a scene for a command. */
#include "cli/cli_scene.h"

#include <stdio.h>
#include <string.h>

#include "cli/cli_outputs.h"
#include "cli/cli_status.h"
#include "io/output_guard.h"
#include "geometry/scene_view.h"
#include "util/progress.h"

int cli_scene_open(cli_scene *c, const char *cmd, const char *scene_path, const cli_scene_use *use,
                   const build_options *opt)
{
    static const cli_scene_use none = {0};
    if (!use) use = &none;
    const char *viewpoint = use->viewpoint, *season = use->season;
    memset(c, 0, sizeof *c);
    err_buf err = {{0}};
    double t0 = progress_now();
    /* all the process did before is start-up: its CPU time, on one thread */
    phase_mark m = phase_start();
    c->times.seconds[PHASE_LIBRARIES] = c->times.cpu[PHASE_LIBRARIES] = m.cpu;
    c->times.thread_cpu[PHASE_LIBRARIES] = m.thread_cpu;
    if (!(c->reg = plugin_registry_open(&err))) return cli_fail(cmd, &err, ERR_INTERNAL);
    m = phase_stop(&c->times, PHASE_PLUGINS, m);
    /* Problems of the scene file speak of it themselves. */
    if (!(c->sf = scene_file_load_with(scene_path, c->reg, (use->no_camera ? SCENE_FILE_NO_CAMERA : 0) | (opt && opt->quiet ? SCENE_FILE_QUIET : 0), &err))) return cli_fail(NULL, &err, ERR_INPUT);
    phase_stop(&c->times, PHASE_SCENE_FILE, m);
    if (viewpoint && scene_file_use_viewpoint(c->sf, viewpoint, &err)) return cli_fail(cmd, &err, ERR_USAGE);
    if (season && scene_file_use_season(c->sf, season, &err)) return cli_fail(cmd, &err, ERR_USAGE);
    if (use->no_build) return use->check_outputs ? cli_outputs_check(cmd, c->sf, use->inputs, use->n_inputs,
                                                                      use->outputs, use->n_outputs) : EXIT_OK;
    build_options bo = opt ? *opt : (build_options){0};
    bo.times = &c->times;
    if (use->build_for) use->build_for(c->sf, &bo, use->build_for_arg);
    if (!(c->scene = scene_build(c->sf, c->reg, &bo, &err))) return cli_fail(NULL, &err, ERR_INPUT);
    c->seconds = progress_now() - t0;
    const double *ph = c->times.seconds; /* loading the file, materials, objects, season: the rest */
    phase_add(&c->times, PHASE_SCENE_OTHER, c->seconds - ph[PHASE_PLUGINS] - ph[PHASE_SCENE_FILE] - ph[PHASE_TERRAIN] -
                                                ph[PHASE_TREES] - ph[PHASE_ECOLOGY]);
    if (use->check_outputs) {
        int rc = cli_outputs_check(cmd, c->sf, use->inputs, use->n_inputs, use->outputs, use->n_outputs);
        if (rc) return rc;
    }
    scene_view view = use->view;
    if (!view.threads) view.threads = bo.threads;
    if (scene_view_prepare(c->scene, &c->sf->ground_cover, &view, &c->times, &err)) return cli_fail(cmd, &err, ERR_INTERNAL);
    return EXIT_OK;
}

void cli_scene_close(cli_scene *c)
{
    scene_free(c->scene);
    scene_file_free(c->sf);
    plugin_registry_free(c->reg);
    output_guard_clear();
    memset(c, 0, sizeof *c);
}
