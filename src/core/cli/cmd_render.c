/* cmd_render.c — `sylva render SCENE`: load, build, render, write EXR and PNG; under mpirun, each
 * rank renders its bands of the frame and rank 0 writes the files (cli/cli_mpi.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli_args.h"
#include "cli/cli_mpi.h"
#include "cli/cli_options.h"
#include "cli/cli_outputs.h"
#include "cli/cli_parts.h"
#include "cli/cli_scene.h"
#include "cli/cli_status.h"
#include "cli/commands.h"
#include "render/render_still.h"
#include "util/progress.h"

static const char render_about[] =
    "Renders SCENE (a YAML scene file) with the path tracer and writes a linear EXR with\n"
    "depth, normal, albedo and id layers plus a tone-mapped PNG.\n";

static const char render_epilogue[] =
    "Under MPI (`mpirun -np N sylva render ...`, in a build with SYLVA_MPI), every rank\n"
    "builds the scene itself (on separate machines as soon as rank 0 could build and\n"
    "broadcast it, with no scene format to keep in step) and renders every N-th band of\n"
    "16 rows; rank 0 gathers the bands, meters the exposure and writes the one PNG and\n"
    "EXR, byte for byte those of a single process. Only rank 0 prints. See docs/mpi.md.\n\n"
    "exit status: 0 done, 1 usage, 2 bad scene or plugin failure, 3 output not written,\n"
    "4 out of memory or internal error\n";

/* Fills png and exr paths from -o (or the scene's stem, and the viewpoint's name and the season
 * after it). */
static int output_paths(const char *scene_path, const char *viewpoint, const char *season, const char *out,
                        char *png, char *exr, size_t n)
{
    char base[4096];
    if (out) {
        size_t l = strlen(out);
        if (l < 5 || (strcmp(out + l - 4, ".png") && strcmp(out + l - 4, ".exr"))) {
            fprintf(stderr, "sylva render: -o must name a .png or .exr file, got '%s'\n", out);
            return -1;
        }
        if (l - 4 >= sizeof base) return -1;
        memcpy(base, out, l - 4);
        base[l - 4] = '\0';
    } else {
        if (cli_scene_stem(scene_path, "", "", base, sizeof base)) return -1;
        size_t l = strlen(base);
        if (viewpoint && (size_t)snprintf(base + l, sizeof base - l, "_%s", viewpoint) >= sizeof base - l) return -1;
        l = strlen(base);
        if (season && (size_t)snprintf(base + l, sizeof base - l, "_%s", season) >= sizeof base - l) return -1;
    }
    if ((size_t)snprintf(png, n, "%s.png", base) >= n || (size_t)snprintf(exr, n, "%s.exr", base) >= n) return -1;
    return 0;
}

static const char *const ground_names[] = {"camera", "development", NULL};

static int render_run(cli_mpi *m, int argc, char **argv)
{
    const char *viewpoint = NULL, *season = NULL;
    const char *scene_path = NULL, *out = NULL;
    render_options ro = {0};
    build_options bo = {0};
    int ground = 0;
    const cli_option options[] = {
        CLI_OPT_PATH("-o, --output", "FILE", out, "FILE.png or FILE.exr; the other format is written beside it "
                     "(default: the scene's name, _VIEWPOINT with --viewpoint and _SEASON with --season, with "
                     ".png in the current folder)"),
        CLI_OPT_WHOLE("--spp", "N", ro.spp, 1, 1u << 20, "samples per pixel (overrides image.spp)"),
        CLI_OPT_SIZE("--size", ro.width, ro.height, "image size in pixels (overrides image.width/height)"),
        CLI_OPT_WHOLE("--threads", "N", bo.threads, 1, 1024, "threads for every phase: tree variants, ecology, ground cover, "
                      "BVH and pixels (default: one per core); the image does not depend on it"),
        {.names = "--seed", .type = CLI_WHOLE, .value = "N", .target = &ro.seed, .target_size = sizeof ro.seed,
         .max = UINT64_MAX, .given = &ro.seed_set, .help = "random seed (overrides image.seed)"},
        CLI_OPT_FLAG("--verify", ro.verify, "verification mode: direct sun with hard shadows plus the constant "
                     "ambient term, no indirect light (as POV-Ray)"),
        CLI_OPT_FLAG("--flat-earth", ro.flat_earth, "straight camera rays even when the scene's earth.curvature "
                     "is on (the view POV-Ray's export gives)"),
        CLI_OPT_TEXT("--viewpoint", "NAME", viewpoint, CLI_HELP_VIEWPOINT),
        CLI_OPT_TEXT("--season", "S", season, CLI_HELP_SEASON),
        CLI_OPT_YEAR(bo),
        CLI_OPT_CHOICE("--ground", ground, ground_names, "the terrain plugin's levels of detail around the camera "
                       "(default) or around the development, one ground for every viewpoint, as `sylva study` "
                       "renders it"),
        CLI_OPTS_SCENE_COMMON(bo),
    };
    const cli_command_spec spec = {"render", "SCENE", render_about, NULL, options, sizeof options / sizeof *options,
                                   render_epilogue, cli_operand_scene, &scene_path};
    int parsed = cli_options_parse(&spec, argc, argv);
    if (parsed) return cli_options_status(parsed);
    ro.threads = bo.threads, ro.quiet = bo.quiet;
    bo.detail_at_development = ground;
    char png[4200], exr[4200];
    if (output_paths(scene_path, viewpoint, season, out, png, exr, sizeof png)) return EXIT_USAGE;
    if (!ro.threads) ro.threads = bo.threads = m->threads;
    if (m->rank) ro.quiet = bo.quiet = 1;

    err_buf err = {{0}};
    render_still_options rs = {.render = ro, .png = png, .exr = exr, .started = progress_now()};
    cli_scene cs;
    cli_parts parts;
    cli_parts_of(&parts, m);
    cli_file outputs[] = {{png, out ? "-o" : "the output"}, {exr, out ? "-o" : "the output"}};
    cli_scene_use use = {.viewpoint = viewpoint, .season = season, .check_outputs = 1, .outputs = outputs,
                         .n_outputs = 2, .view = {.picture = 1, .width = ro.width, .height = ro.height, .quiet = ro.quiet}};
    int rc = cli_scene_open(&cs, "render", scene_path, &use, &bo);
    rs.scene_seconds = cs.seconds;
    if (!rc && render_still_run(cs.scene, &rs, &parts.parts, &cs.times, &err)) rc = cli_parts_fail(&parts, &err);
    if (!rc && !m->rank) printf("%s\n%s\n", png, exr);
    cli_scene_close(&cs);
    return rc;
}

int cmd_render(int argc, char **argv)
{
    cli_mpi m;
    int rc = cli_mpi_begin(&m, "render", argc, argv);
    if (!rc) rc = render_run(&m, argc, argv);
    return cli_mpi_end(&m, rc);
}
