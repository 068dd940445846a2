/* cmd_crosscheck.c — `sylva crosscheck SCENE`: render the scene in sylva's verification mode and
 * with POV-Ray from its export, compare, write the report; the exit status says whether the
 * thresholds hold. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli_args.h"
#include "cli/cli_options.h"
#include "cli/cli_outputs.h"
#include "cli/cli_scene.h"
#include "cli/cli_status.h"
#include "cli/commands.h"
#include "crosscheck/crosscheck_scene.h"
#include "geometry/cutout_outline.h"

enum { EXIT_DISAGREE = 5 }; /* both renders compared; a threshold does not hold */

static const char crosscheck_about[] =
    "Renders SCENE in sylva's verification mode and with POV-Ray 3.7 from its export, at the\n"
    "same size with the same camera samples (pixel centre plus a regular grid, no jitter),\n"
    "compares the two in linear float overall and per class (terrain, bark, leaves,\n"
    "objects, sky) and writes DIR/report.html and DIR/metrics.json with both pictures, a\n"
    "difference heatmap and both renderers' timing (see docs/crosscheck.md). POV-Ray cannot\n"
    "bend rays: a scene with earth.curvature on is compared on a flat Earth, and the report\n"
    "says so.\n";

static const char crosscheck_epilogue[] =
    "Prints the verdict and the report's path.\n"
    "exit status: 0 the renders agree within the thresholds, 5 they do not, 1 usage,\n"
    "2 bad scene or plugin failure, 3 output not written, 4 POV-Ray missing or failing,\n"
    "out of memory or internal error\n";

int cmd_crosscheck(int argc, char **argv)
{
    const char *viewpoint = NULL, *season = NULL;
    const char *scene_path = NULL, *out = NULL;
    crosscheck_options co = {0};
    crosscheck_default_thresholds(&co.thresholds);
    crosscheck_thresholds *t = &co.thresholds;
    build_options bo = {0};
    int leaves = LEAF_MODE_AUTO;
    static const char *const leaf_names[] = {"auto", "mask", "outline", NULL};
    char class_help[128];
    snprintf(class_help, sizeof class_help, "MAE within each class covering >= %g of the picture at most X",
             t->min_class_share);
    const cli_option options[] = {
        CLI_OPT_PATH("-o, --output", "DIR", out, "output folder (default: crosscheck-<scene name>)"),
        CLI_OPT_SIZE("--size", co.width, co.height, "image size (default: the scene's)"),
        CLI_OPT_WHOLE("--spp", "N", co.spp, 1, 1u << 16, "samples per pixel, rounded down to a square (default: "
                      "the scene's)"),
        CLI_OPT_WHOLE("--threads", "N", bo.threads, 1, 1024, "threads for the scene build and both renderers "
                      "(default: one per core)"),
        CLI_OPT_PATH("--povray", "PATH", co.povray, "POV-Ray's executable (default: $SYLVA_POVRAY, else povray)"),
        CLI_OPT_PATH("--pov", "FILE.pov", co.pov_scene, "compare against this POV-Ray scene instead of exporting "
                     "SCENE (an export for the same size, e.g. edited by hand)"),
        CLI_OPT_NUMBER("--min-coverage", "F", "a number", t->min_coverage_agreement, 0, 1, CLI_DEFAULT,
                       "coverage agreement at least F"),
        CLI_OPT_NUMBER("--max-mae", "X", "a number", t->max_mae, 0, 1e30, CLI_DEFAULT, "mean absolute error at most X"),
        CLI_OPT_NUMBER("--over-error", "X", "a number", t->over_error, 0, 1e30, CLI_DEFAULT, "a pixel is over when "
                       "a channel differs by more than X"),
        CLI_OPT_NUMBER("--max-over", "F", "a number", t->max_over_fraction, 0, 1, CLI_DEFAULT, "share of over pixels "
                       "at most F"),
        CLI_OPT_NUMBER("--max-class-mae", "X", "a number", t->max_class_mae, 0, 1e30, CLI_DEFAULT, class_help),
        CLI_OPT_CHOICE("--leaves", leaves, leaf_names, "alpha-masked leaves drawn by both renderers as their "
                       "masks, or as opaque outline polygons (fast in POV-Ray); auto: outlines when the "
                       "scene holds more than 200,000 cut-out triangles (default auto)"),
        CLI_OPT_TEXT("--viewpoint", "NAME", viewpoint, CLI_HELP_VIEWPOINT),
        CLI_OPT_TEXT("--season", "S", season, CLI_HELP_SEASON),
        CLI_OPT_YEAR(bo),
        CLI_OPTS_SCENE_COMMON(bo),
    };
    const cli_command_spec spec = {"crosscheck", "SCENE", crosscheck_about, NULL, options,
                                   sizeof options / sizeof *options, crosscheck_epilogue, cli_operand_scene,
                                   &scene_path};
    int parsed = cli_options_parse(&spec, argc, argv);
    if (parsed) return cli_options_status(parsed);
    co.threads = bo.threads, co.quiet = bo.quiet;
    co.planting_shown = bo.planting_shown, co.planting_years = bo.planting_years;
    size_t pl = co.pov_scene ? strlen(co.pov_scene) : 0;
    if (co.pov_scene && (pl < 5 || strcmp(co.pov_scene + pl - 4, ".pov"))) {
        fprintf(stderr, "sylva crosscheck: --pov must name a .pov file, got '%s'\n", co.pov_scene);
        return EXIT_USAGE;
    }
    char out_default[4096];
    if (!out) {
        if (cli_scene_stem(scene_path, "crosscheck-", "", out_default, sizeof out_default)) {
            fprintf(stderr, "sylva crosscheck: the scene's name is too long for an output folder\n");
            return EXIT_USAGE;
        }
        out = out_default;
    }
    co.source = scene_path;

    err_buf err = {{0}};
    cli_scene cs;
    cli_scene_use use = {.viewpoint = viewpoint, .season = season, .check_outputs = 1, /* the folder's files */
                         .view = {.picture = 1, .width = co.width, .height = co.height, .quiet = co.quiet}};
    int rc = cli_scene_open(&cs, "crosscheck", scene_path, &use, &bo);
    cutout_outline_stats ls;
    int outlined = rc ? 0 : cutout_outline_apply(cs.scene, (leaf_mode)leaves, &ls, &err);
    if (outlined < 0) rc = cli_fail("crosscheck", &err, ERR_INTERNAL);
    if (outlined > 0) {
        co.outline_cutouts = ls.cutout_triangles;
        co.outline_triangles = ls.outline_triangles;
        if (!co.quiet)
            fprintf(stderr, "crosscheck: leaves drawn as outlines by both renderers: %llu cut-out triangles of %u "
                            "materials replaced by %llu opaque ones\n", (unsigned long long)ls.cutout_triangles,
                    ls.materials, (unsigned long long)ls.outline_triangles);
    }
    crosscheck_result *r = rc ? NULL : crosscheck_scene(cs.scene, out, &co, &err);
    if (r) {
        printf("%s\n%s/report.html\n", r->verdict, out);
        rc = r->pass ? EXIT_OK : EXIT_DISAGREE;
    } else if (!rc) {
        rc = cli_fail("crosscheck", &err, ERR_INTERNAL);
    }
    free(r);
    cli_scene_close(&cs);
    return rc;
}
