/* cmd_factors.c — `sylva factors SCENE -o DIR`: the ecology's terrain factors on its patch grid
 * (altitude, slope, humidity, windiness, sunniness, water) as one PNG map each and one CSV of
 * every patch's values. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli_args.h"
#include "cli/cli_options.h"
#include "cli/cli_ecology.h"
#include "cli/cli_outputs.h"
#include "cli/cli_status.h"
#include "cli/commands.h"
#include "io/output_folder.h"
#include "io/atomic_file.h"
#include "scene_build/ecology_maps.h"

static const char factors_about[] =
    "Computes the terrain factors the scene's ecology grows plants by, on its patch grid, and\n"
    "writes each as DIR/NAME.png (dark 0 to bright 1; north up) and all of them, one row a\n"
    "patch, as DIR/factors.csv. The folder is created when missing.\n";

static const char factors_epilogue[] =
    "exit status: 0 done, 1 usage, 2 bad scene or plugin failure, 3 output not written,\n"
    "4 out of memory or internal error\n";

/* factors.csv: i, k, the patch centre, then each map's value. */
static int write_csv(const char *path, const sylva_ecology_factor_map *maps, uint32_t n, err_buf *err)
{
    atomic_file out;
    FILE *f = atomic_file_open_stream(&out, path, err);
    if (!f) return -1;
    fprintf(f, "i,k,x,y");
    for (uint32_t m = 0; m < n; m++) fprintf(f, ",%s", maps[m].name);
    fputc('\n', f);
    const sylva_ecology_factor_map *g = &maps[0];
    for (uint32_t k = 0; k < g->ny; k++)
        for (uint32_t i = 0; i < g->nx; i++) {
            fprintf(f, "%u,%u,%.3f,%.3f", i, k, g->x0 + (i + 0.5) * g->dx, g->y0 + (k + 0.5) * g->dy);
            for (uint32_t m = 0; m < n; m++) fprintf(f, ",%.6f", maps[m].values[(size_t)k * g->nx + i]);
            fputc('\n', f);
        }
    return atomic_file_commit(&out, err);
}

int cmd_factors(int argc, char **argv)
{
    const char *scene_path = NULL, *dir = NULL;
    build_options bo = {.analysis = 1}; /* the ground as surveyed, whatever the camera */
    const cli_option options[] = {
        {.names = "-o, --output", .type = CLI_PATH, .value = "DIR", .target = &dir, .flags = CLI_REQUIRED,
         .help = "folder for the maps (required)"},
        CLI_OPTS_SCENE_COMMON(bo),
    };
    const cli_command_spec spec = {"factors", "SCENE", factors_about, NULL, options, sizeof options / sizeof *options,
                                   factors_epilogue, cli_operand_scene, &scene_path};
    int parsed = cli_options_parse(&spec, argc, argv);
    if (parsed) return cli_options_status(parsed);
    cli_ecology e;
    int rc = cli_ecology_open(&e, "factors", scene_path, &bo);
    if (!rc) rc = cli_outputs_check("factors", e.base.sf, NULL, 0, NULL, 0); /* the folder's files */
    if (rc) {
        cli_ecology_close(&e);
        return rc;
    }
    err_buf err = {{0}};
    uint32_t n = ecology_session_factor_count(e.session);
    sylva_ecology_factor_map *maps = calloc(n ? n : 1, sizeof *maps);
    if (!maps) {
        cli_ecology_close(&e);
        return cli_failf("factors", ERR_NOMEM, "out of memory");
    }
    for (uint32_t m = 0; m < n && !rc; m++)
        if (ecology_session_factor(e.session, m, &maps[m], &err)) rc = cli_fail("factors", &err, ERR_PLUGIN);
    if (!rc && n && output_folder_make(dir, &err)) rc = cli_fail("factors", &err, ERR_OUTPUT);
    char path[4200];
    for (uint32_t m = 0; m < n && !rc; m++) {
        snprintf(path, sizeof path, "%s/%s.png", dir, maps[m].name);
        if (factor_map_write(path, &maps[m], &err)) {
            rc = cli_fail("factors", &err, ERR_OUTPUT);
        } else {
            printf("%s\n", path);
        }
    }
    if (!rc && n) {
        snprintf(path, sizeof path, "%s/factors.csv", dir);
        if (write_csv(path, maps, n, &err)) {
            rc = cli_fail("factors", &err, ERR_OUTPUT);
        } else {
            printf("%s\n", path);
        }
    }
    if (!rc && !bo.quiet)
        fprintf(stderr, "factors: %u maps of %u x %u patches of %.2f x %.2f m\n", n, maps[0].nx, maps[0].ny, maps[0].dx,
                maps[0].dy);
    free(maps);
    cli_ecology_close(&e);
    return rc;
}
