/* cli_scene.h — what every command that works on a scene file starts with: the plugin registry,
 * the validated scene file and the scene built from it, each problem printed once (a located
 * scene-file sentence as it is, anything else prefixed with "sylva CMD: "). */
#ifndef SYLVA_CLI_SCENE_H
#define SYLVA_CLI_SCENE_H

#include "plugin/plugin_host.h"
#include "scene/scene.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "util/phase_times.h"

typedef struct cli_scene {
    plugin_registry *reg;  /* owned */
    scene_file *sf;        /* owned */
    scene *scene;          /* owned */
    double seconds;        /* to load and build */
    phase_times times;     /* the scene build's phases and the ground cover; a command adds its own */
} cli_scene;

/* Fills c and returns EXIT_OK, or the exit status of the problem after printing it
 * (cli_fail); in every case cli_scene_close releases what was made. viewpoint: NULL for the
 * scene's camera, or the name of one of its viewpoints (--viewpoint) to build the scene with.
 * season: NULL for the scene's season: key, or a season's name or date (--season). */
int cli_scene_open(cli_scene *c, const char *cmd, const char *scene_path, const char *viewpoint,
                   const char *season, const build_options *opt);
void cli_scene_close(cli_scene *c);

/* Adds the scene file's ground cover (geometry/ground_cover_place.h) for c's camera and an image
 * width x height pixels (0: the scene's size), and says on stderr how many tufts stand within
 * what radius unless quiet. Returns EXIT_OK or the exit status after printing the problem. */
int cli_scene_ground_cover(cli_scene *c, const char *cmd, uint32_t width, uint32_t height, int quiet);

#endif
