/* cli_ecology.h — what `sylva simulate` and `sylva factors` share: loading a scene, building
 * its terrain and species without the ecology, and starting the ecology session on them. */
#ifndef SYLVA_CLI_ECOLOGY_H
#define SYLVA_CLI_ECOLOGY_H

#include "cli/cli_scene.h"
#include "scene_build/ecology_session.h"

typedef struct cli_ecology {
    cli_scene base;           /* owned: registry, scene file, scene built without the ecology */
    ecology_session *session; /* owned */
} cli_ecology;

/* Fills e; returns EXIT_OK, or the exit status of the problem after printing it (cli_fail). */
int cli_ecology_open(cli_ecology *e, const char *cmd, const char *scene_path, const build_options *opt);
void cli_ecology_close(cli_ecology *e);

#endif
