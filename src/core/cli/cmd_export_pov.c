/* cmd_export_pov.c — `sylva export-pov SCENE`: load, build, write POV-Ray 3.7 scene files (the
 * whole scene, or one species for use in another POV-Ray scene). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli_args.h"
#include "cli/cli_options.h"
#include "cli/cli_outputs.h"
#include "cli/cli_scene.h"
#include "cli/cli_status.h"
#include "cli/commands.h"
#include "geometry/cutout_outline.h"
#include "pov/pov_export_run.h"

static const char export_pov_about[] =
    "Writes SCENE (a YAML scene file) as POV-Ray 3.7 scene files: OUT.pov with the camera,\n"
    "sun, sky and includes beside it for the materials, terrain, objects, species (each\n"
    "variant declared once as a mesh2) and plants (one `object { Species_k matrix <..> }`\n"
    "each), plus the images of textured materials. Rendered by POV-Ray from the output\n"
    "folder, it gives the picture of `sylva render --verify` (see docs/crosscheck.md); a scene\n"
    "with earth.curvature on is written as seen on a flat Earth (render --flat-earth), as\n"
    "POV-Ray cannot bend rays.\n";

static const char export_pov_epilogue[] =
    "Prints the path of the main file written.\n"
    "exit status: 0 done, 1 usage, 2 bad scene, plugin failure or unknown species,\n"
    "3 output not written, 4 out of memory or internal error\n";

int cmd_export_pov(int argc, char **argv)
{
    const char *viewpoint = NULL, *season = NULL;
    const char *scene_path = NULL, *out = NULL, *species_name = NULL;
    pov_export_options po = {0};
    build_options bo = {0};
    uint64_t variant = 0;
    int variant_given = 0;
    int leaves = LEAF_MODE_MASK;
    static const char *const leaf_names[] = {"auto", "mask", "outline", NULL};
    const cli_option options[] = {
        CLI_OPT_PATH("-o, --output", "FILE", out, "OUT.pov (default: the scene's name with .pov in the current "
                     "folder); with --species also OUT.inc alone"),
        CLI_OPT_SIZE("--size", po.width, po.height, "image size the camera's aspect ratio is written for (default: "
                     "the scene's image.width/height)"),
        CLI_OPT_WHOLE("--spp", "N", po.spp, 1, 1u << 20, "samples per pixel the render command in OUT.pov matches"),
        CLI_OPT_TEXT("--species", "NAME", species_name, "one species only: OUT.inc declares its variants (base at "
                     "the origin, growing along +Z) with their materials; OUT.pov adds a small scene showing them "
                     "side by side"),
        {.names = "--variant", .type = CLI_WHOLE, .value = "K", .target = &variant, .target_size = sizeof variant,
         .max = 1u << 20, .given = &variant_given, .help = "with --species: variant K only (0 is the youngest)"},
        CLI_OPT_CHOICE("--leaves", leaves, leaf_names, "alpha-masked leaves as their masks (default) or as opaque "
                       "outline polygons, as `sylva crosscheck --leaves` draws them; auto as crosscheck's"),
        CLI_OPT_TEXT("--viewpoint", "NAME", viewpoint, CLI_HELP_VIEWPOINT),
        CLI_OPT_TEXT("--season", "S", season, CLI_HELP_SEASON),
        CLI_OPT_YEAR(bo),
        CLI_OPTS_SCENE_COMMON(bo),
    };
    const cli_command_spec spec = {"export-pov", "SCENE", export_pov_about, NULL, options,
                                   sizeof options / sizeof *options, export_pov_epilogue, cli_operand_scene,
                                   &scene_path};
    int parsed = cli_options_parse(&spec, argc, argv);
    if (parsed) return cli_options_status(parsed);
    if (variant_given && !species_name) {
        fprintf(stderr, "sylva export-pov: --variant needs --species NAME\n");
        return EXIT_USAGE;
    }
    char out_default[4096];
    if (!out) {
        if (cli_scene_stem(scene_path, "", ".pov", out_default, sizeof out_default)) {
            fprintf(stderr, "sylva export-pov: the scene's name is too long for an output name\n");
            return EXIT_USAGE;
        }
        out = out_default;
    }
    size_t ol = strlen(out);
    int out_pov = ol > 4 && !strcmp(out + ol - 4, ".pov"), out_inc = ol > 4 && !strcmp(out + ol - 4, ".inc");
    if (!out_pov && !(species_name && out_inc)) {
        fprintf(stderr, "sylva export-pov: -o must name a .pov file%s, got '%s'\n",
                species_name ? " or, with --species, an .inc file" : "", out);
        return EXIT_USAGE;
    }

    err_buf err = {{0}};
    cli_scene cs;
    cli_file output = {out, out == out_default ? "the output" : "-o"};
    cli_scene_use use = {.viewpoint = viewpoint, .season = season, .check_outputs = 1, .outputs = &output,
                         .n_outputs = 1, .view = {.picture = !species_name, .width = po.width, .height = po.height,
                                                  .quiet = bo.quiet}};
    int rc = cli_scene_open(&cs, "export-pov", scene_path, &use, &bo);
    pov_export_request req = {.scene = po, .out = out, .source = scene_path, .species = species_name,
                              .variant = variant_given ? (int32_t)variant : -1, .quiet = bo.quiet,
                              .scene_seconds = cs.seconds};
    cutout_outline_stats ls;
    if (!rc && cutout_outline_apply(cs.scene, (leaf_mode)leaves, &ls, &err) < 0) rc = cli_fail("export-pov", &err, ERR_INTERNAL);
    if (!rc && pov_export_run(cs.scene, &req, &err)) rc = cli_fail("export-pov", &err, ERR_INTERNAL);
    if (!rc) printf("%s\n", out);
    cli_scene_close(&cs);
    return rc;
}
