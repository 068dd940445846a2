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
#include "pov/pov_write.h"
#include "util/progress.h"

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
        CLI_OPT_TEXT("--viewpoint", "NAME", viewpoint, CLI_HELP_VIEWPOINT),
        CLI_OPT_TEXT("--season", "S", season, CLI_HELP_SEASON),
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
    int rc = cli_scene_open(&cs, "export-pov", scene_path, viewpoint, season, &bo);
    cli_file output = {out, out == out_default ? "the output" : "-o"};
    if (!rc) rc = cli_outputs_check("export-pov", cs.sf, NULL, 0, &output, 1);
    if (!rc && !species_name) rc = cli_scene_ground_cover(&cs, "export-pov", po.width, po.height, bo.quiet);
    if (rc) goto done;
    const scene *sc = cs.scene;
    double t1 = progress_now();
    pov_export_stats st;
    if (species_name) {
        uint32_t k = 0;
        while (k < sc->n_species && strcmp(sc->species[k].name, species_name)) k++;
        if (k == sc->n_species) {
            char names[ERR_MSG_MAX / 2] = "";
            for (uint32_t j = 0, used = 0; j < sc->n_species && used < sizeof names; j++)
                used += (uint32_t)snprintf(names + used, sizeof names - used, "%s '%s'", j ? "," : "", sc->species[j].name);
            rc = cli_failf("export-pov", ERR_INPUT, "the scene has no species '%s'; it has:%s", species_name,
                           sc->n_species ? names : " none");
            goto done;
        }
        if (variant_given && variant >= sc->species[k].n_variants) {
            rc = cli_failf("export-pov", ERR_INPUT, "species '%s' has variants 0 to %u; --variant %lld does not exist",
                           species_name, sc->species[k].n_variants ? sc->species[k].n_variants - 1 : 0,
                           (long long)variant);
            goto done;
        }
        if (pov_export_species(sc, k, variant_given ? (int32_t)variant : -1, out, scene_path, &st, &err)) {
            rc = cli_fail("export-pov", &err, ERR_OUTPUT);
            goto done;
        }
    } else {
        po.source = scene_path;
        if (sc->earth.curvature && !bo.quiet)
            fprintf(stderr, "sylva export-pov: note: POV-Ray cannot bend rays for the Earth's curvature "
                            "(earth.curvature is on); the exported scene shows it on a flat Earth, as "
                            "sylva render --flat-earth would\n");
        if (pov_export_scene(sc, out, &po, &st, &err)) {
            rc = cli_fail("export-pov", &err, ERR_OUTPUT);
            goto done;
        }
    }
    if (!bo.quiet)
        fprintf(stderr, "exported %u files, %.1f MB (%llu plants, %llu left out) in %.2fs; scene built in %.2fs\n", st.files,
                st.bytes / 1e6, (unsigned long long)st.instances, (unsigned long long)st.skipped, progress_now() - t1,
                cs.seconds);
    printf("%s\n", out);
done:
    cli_scene_close(&cs);
    return rc;
}
