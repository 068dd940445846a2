/* cli_scene.c — loading and building a scene for a command. */
#include "cli/cli_scene.h"

#include <stdio.h>
#include <string.h>

#include "cli/cli_status.h"
#include "io/output_guard.h"
#include "geometry/ground_cover_place.h"
#include "util/progress.h"

/* The commands that draw no picture, for which a scene needs no camera: section; a quiet run's
 * loader prints no info lines. */
static unsigned load_flags(const char *cmd, const build_options *opt)
{
    unsigned flags = cmd && (!strcmp(cmd, "ztv") || !strcmp(cmd, "probe")) ? SCENE_FILE_NO_CAMERA : 0;
    return flags | (opt && opt->quiet ? SCENE_FILE_QUIET : 0);
}

int cli_scene_open(cli_scene *c, const char *cmd, const char *scene_path, const char *viewpoint,
                   const char *season, const build_options *opt)
{
    memset(c, 0, sizeof *c);
    err_buf err = {{0}};
    double t0 = progress_now();
    if (!(c->reg = plugin_registry_open(&err))) return cli_fail(cmd, &err, ERR_INTERNAL);
    /* Problems of the scene file speak of it themselves. */
    if (!(c->sf = scene_file_load_with(scene_path, c->reg, load_flags(cmd, opt), &err))) return cli_fail(NULL, &err, ERR_INPUT);
    if (viewpoint && scene_file_use_viewpoint(c->sf, viewpoint, &err)) return cli_fail(cmd, &err, ERR_USAGE);
    if (season && scene_file_use_season(c->sf, season, &err)) return cli_fail(cmd, &err, ERR_USAGE);
    build_options bo = opt ? *opt : (build_options){0};
    bo.times = &c->times;
    if (!(c->scene = scene_build(c->sf, c->reg, &bo, &err))) return cli_fail(NULL, &err, ERR_INPUT);
    c->seconds = progress_now() - t0;
    const double *ph = c->times.seconds; /* loading the file, materials, objects, season: the rest */
    phase_add(&c->times, PHASE_SCENE_OTHER, c->seconds - ph[PHASE_TERRAIN] - ph[PHASE_TREES] - ph[PHASE_ECOLOGY]);
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

int cli_scene_ground_cover(cli_scene *c, const char *cmd, uint32_t width, uint32_t height, int quiet)
{
    err_buf err = {{0}};
    ground_cover_report rep;
    if (!width || !height) width = c->scene->image.width, height = c->scene->image.height;
    phase_mark t0 = phase_start();
    if (ground_cover_add(c->scene, &c->sf->ground_cover, width, height, &rep, &err)) return cli_fail(cmd, &err, ERR_INTERNAL);
    phase_stop(&c->times, PHASE_GROUND_COVER, t0);
    if (!quiet && rep.instances)
        fprintf(stderr, "ground cover: %u tufts within %.0f m (a blade spans a pixel at %.0f m)%s\n", rep.instances,
                rep.radius, rep.pixel_radius, rep.capped ? ", the radius shrunk to max_instances" : "");
    return EXIT_OK;
}
