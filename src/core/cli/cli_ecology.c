/* cli_ecology.c — the scene and ecology session behind `sylva simulate` and `sylva factors`. */
#include "cli/cli_ecology.h"

#include <string.h>

#include "cli/cli_status.h"

int cli_ecology_open(cli_ecology *e, const char *cmd, const char *scene_path, const build_options *opt)
{
    memset(e, 0, sizeof *e);
    build_options bo = *opt;
    bo.no_ecology = 1;
    int rc = cli_scene_open(&e->base, cmd, scene_path, NULL, &bo);
    if (rc) return rc;
    err_buf err = {{0}};
    if (!(e->session = ecology_session_open(e->base.sf, e->base.scene, e->base.reg, opt, &err)))
        return cli_fail(NULL, &err, ERR_INPUT);
    return EXIT_OK;
}

void cli_ecology_close(cli_ecology *e)
{
    ecology_session_free(e->session);
    cli_scene_close(&e->base);
    memset(e, 0, sizeof *e);
}
