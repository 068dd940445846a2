/* cli_ecology.c — the scene and ecology session behind `sylva simulate` and `sylva factors`. */
#include "cli/cli_ecology.h"

#include <errno.h>
#include <string.h>
#include <sys/stat.h>

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

int cli_make_folder(const char *dir, err_buf *err)
{
    struct stat st;
    if (!stat(dir, &st)) {
        if (S_ISDIR(st.st_mode)) return 0;
        return err_fail(err, ERR_OUTPUT, "%s: exists and is not a folder", dir);
    }
    if (mkdir(dir, 0777)) return err_fail(err, ERR_OUTPUT, "%s: cannot create the folder: %s", dir, strerror(errno));
    return 0;
}
