/* cli_scene.h — what every command that works on a scene file starts with: the plugin registry,
 * the validated scene file and the scene built from it, each problem printed once (a located
 * scene-file sentence as it is, anything else prefixed with "sylva CMD: "). */
#ifndef SYLVA_CLI_SCENE_H
#define SYLVA_CLI_SCENE_H

#include "cli/cli_outputs.h"
#include "geometry/scene_view.h"
#include "plugin/plugin_host.h"
#include "scene/scene.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "util/phase_times.h"

/* What a command makes of the scene, which decides the steps cli_scene_open takes. */
typedef struct cli_scene_use {
    const char *viewpoint; /* NULL: the scene's camera; else one of its viewpoints (--viewpoint) */
    const char *season;    /* NULL: the scene's season: key; else a season's name or a date (--season) */
    int no_camera;         /* 1: an analysis (ztv, probe): the scene needs no camera: section */
    int no_build;          /* 1: the file loaded and checked and the outputs with it, the scene left
                              to the command (a study builds it once it knows there is work) */
    int check_outputs;     /* 1: check the outputs against what the run reads (cli_outputs.h) */
    const cli_file *inputs, *outputs; /* with check_outputs: the files the command line names */
    uint32_t n_inputs, n_outputs;
    scene_view view;       /* the steps of a scene drawn from its camera (geometry/scene_view.h) */
    /* NULL, or what the command makes of the loaded scene file for its build (called before the
     * build, with the command's build options to change and build_for_arg): a bare-earth map
     * leaves the plants out */
    void (*build_for)(const scene_file *sf, build_options *bo, const void *arg);
    const void *build_for_arg;
} cli_scene_use;

typedef struct cli_scene {
    plugin_registry *reg;  /* owned */
    scene_file *sf;        /* owned */
    scene *scene;          /* owned */
    double seconds;        /* to load and build */
    phase_times times;     /* the scene build's phases and the ground cover; a command adds its own */
} cli_scene;

/* Loads and builds the scene for `use` (NULL: as it is, nothing checked), checks the outputs and
 * takes the steps of its view when use asks. Fills c and returns EXIT_OK, or the exit status of
 * the problem after printing it (cli_fail); in every case cli_scene_close releases what was
 * made. */
int cli_scene_open(cli_scene *c, const char *cmd, const char *scene_path, const cli_scene_use *use,
                   const build_options *opt);
void cli_scene_close(cli_scene *c);

#endif
