/* cmd_montage.c — `sylva montage SCENE -o DIR`: the scene's development rendered into its
 * photograph with the camera matched to control points (montage/montage_run.h,
 * docs/photomontage.md). */
#include <stdio.h>
#include <string.h>

#include "cli/cli_args.h"
#include "cli/cli_options.h"
#include "cli/cli_outputs.h"
#include "cli/cli_scene.h"
#include "cli/cli_status.h"
#include "cli/commands.h"
#include "io/output_folder.h"
#include "montage/montage_run.h"

static const char montage_about[] =
    "Renders SCENE's development (the objects marked development: true) into the photograph\n"
    "of its photo: section: the camera matched to the control points, the terrain and the\n"
    "trees in front of the development hiding it, its shadows darkening the photograph.\n"
    "Writes into DIR (created when missing): montage.png and montage.exr, mask.png (the\n"
    "development's coverage), existing.png (the photograph as it is), wireline.png (the\n"
    "development's outline and edges over the photograph), the verification sheet (sheet.pdf,\n"
    "sheet.png: A3, real fonts, the wireline as vector strokes) and with control points\n"
    "residuals.csv. See docs/photomontage.md.\n";

static const char montage_epilogue[] =
    "exit status: 0 done, 1 usage, 2 bad scene, photograph or control points (or points\n"
    "that cannot fix the camera), 3 output not written, 4 out of memory or internal error\n";

int cmd_montage(int argc, char **argv)
{
    const char *scene_path = NULL, *season = NULL;
    montage_options mo = {0};
    build_options bo = {0};
    const cli_option options[] = {
        {.names = "-o, --output", .type = CLI_PATH, .value = "DIR", .target = &mo.dir, .flags = CLI_REQUIRED,
         .help = "folder for the files (required)"},
        CLI_OPT_PATH("--photo", "IMG", mo.photo, "the photograph (default: photo: file)"),
        CLI_OPT_PATH("--control-points", "FILE", mo.points, "the control points (default: photo: control_points)"),
        CLI_OPT_WHOLE("--spp", "N", mo.spp, 1, 1u << 20, "samples per pixel (default: the scene's)"),
        CLI_OPT_NUMBER("--dpi", "N", "pixels per inch", mo.dpi, 0, 10000, CLI_OPEN_LOW,
                       "pixels per inch of the sheet's page and pictures (default: the study: section's, 300)"),
        CLI_OPT_WHOLE("--threads", "N", bo.threads, 1, 1024, "threads for every phase (default: one per core)"),
        CLI_OPT_TEXT("--season", "S", season, CLI_HELP_SEASON),
        CLI_OPT_YEAR(bo),
        CLI_OPTS_SCENE_COMMON(bo),
    };
    const cli_command_spec spec = {"montage", "SCENE", montage_about, NULL, options, sizeof options / sizeof *options,
                                   montage_epilogue, cli_operand_scene, &scene_path};
    int parsed = cli_options_parse(&spec, argc, argv);
    if (parsed) return cli_options_status(parsed);
    mo.threads = bo.threads, mo.quiet = bo.quiet;
    err_buf err = {{0}};
    cli_scene cs;
    montage_report rep = {0};
    cli_file inputs[] = {{mo.photo, "--photo"}, {mo.points, "--control-points"}};
    cli_scene_use use = {.season = season, .check_outputs = 1, .inputs = inputs, .n_inputs = 2};
    int rc = cli_scene_open(&cs, "montage", scene_path, &use, &bo);
    if (!rc && output_folder_make(mo.dir, &err)) rc = cli_fail("montage", &err, ERR_OUTPUT);
    if (!rc && montage_run(cs.scene, cs.sf, &mo, &rep, &err)) rc = cli_fail("montage", &err, ERR_INPUT);
    if (!rc) printf("%s\n", mo.dir);
    montage_report_free(&rep);
    cli_scene_close(&cs);
    return rc;
}
