/* cmd_ztv.c — `sylva ztv SCENE -o DIR`: the zone of theoretical visibility of the scene's
 * development (docs/ztv.md): for every cell of a map over the terrain, how many of the
 * development's targets an observer standing there sees, on bare earth and screened by the
 * forest and the buildings, written as GeoTIFFs, PNG maps and a summary. Under mpirun each rank
 * traces every N-th row of the map and rank 0 writes the files (cli/cli_mpi.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli_mpi.h"
#include "cli/cli_options.h"
#include "cli/cli_outputs.h"
#include "cli/cli_parts.h"
#include "cli/cli_scene.h"
#include "cli/cli_status.h"
#include "cli/commands.h"
#include "ztv/ztv_raster.h"
#include "ztv/ztv_study.h"

static const char ztv_about[] =
    "Maps where SCENE's development can be seen from (a zone of theoretical visibility):\n"
    "for every cell of a grid over the terrain, an observer at eye height above the ground\n"
    "looks for each target of the development (the scene's ztv: section: targets given by\n"
    "hand, heights above each development object, or points sampled on them) along a\n"
    "sightline over the curved Earth (earth: section), on bare earth and screened by what\n"
    "the scene holds. Writes into DIR (created when missing): ztv_bare.tif and ztv_MODE.tif\n"
    "(GeoTIFF on the site's CRS: targets visible, fraction visible, cell class, developments\n"
    "seen), ztv_hidden_MODE.tif (what the screening hides), PNG maps of each,\n"
    "ztv_summary.csv / .json (areas in km2), and ztv_layers.gpkg (the viewpoints, distance\n"
    "rings and structures) with QGIS styles (.qml, and in its layer_styles table) so that the\n"
    "map opens styled in QGIS. See docs/ztv.md.\n";

static const char ztv_epilogue[] =
    "Under MPI (`mpirun -np N sylva ztv ...`, in a build with SYLVA_MPI), every rank builds\n"
    "the scene itself (on separate machines as soon as rank 0 could build and broadcast\n"
    "it, with no scene format to keep in step) and traces every N-th row of the map; rank 0\n"
    "gathers the rows and writes the files, byte for byte those of a single process. Only\n"
    "rank 0 prints. See docs/mpi.md.\n\n"
    "exit status: 0 done, 1 usage, 2 bad scene, plugin failure or nothing to map, 3 output\n"
    "not written, 4 out of memory or internal error\n";

static const char *const screening_names[] = {"none", "vegetation", "all", "canopy", NULL}; /* ztv_mode's order */
static const char *const ground_names[] = {"surveyed", "refined", NULL};

static int ztv_run(cli_mpi *m, int argc, char **argv)
{
    const char *scene_path = NULL, *season = NULL;
    ztv_study_options o = {.radius = NAN, .cell = NAN, .eye = NAN, .screening = -1};
    build_options bo = {.analysis = 1}; /* the ground as surveyed, whatever the camera */
    int refined = 0;
    const cli_option options[] = {
        {.names = "-o, --output", .type = CLI_PATH, .value = "DIR", .target = &o.dir, .flags = CLI_REQUIRED,
         .help = "folder for the maps (required)"},
        CLI_OPT_NUMBER("--radius", "M", "metres", o.radius, 0, 1e7, 0, "map cells within M metres of the nearest "
                       "target (0: the whole terrain)"),
        CLI_OPT_NUMBER("--cell", "M", "metres", o.cell, 0, 1e6, 0, "cell size in metres (0: one cell per terrain node)"),
        CLI_OPT_NUMBER("--observer-height", "M", "metres", o.eye, 0, 1e4, 0, "eye height above the ground (default 2)"),
        CLI_OPT_CHOICE("--screening", o.screening, screening_names, "what screens besides bare earth (default all: "
                       "the plants and the objects; canopy: the surface of the canopy: section's heights)"),
        CLI_OPT_CHOICE("--ground", refined, ground_names, "the ground the sightlines trace: the DTM as surveyed "
                       "(default; a ZTV is a property of the DTM and the development), or the terrain plugin's "
                       "refinement, with its levels of detail around the development, not the camera"),
        CLI_OPT_FLAG("--flat-earth", o.flat_earth, "straight sightlines, whatever the earth: section says"),
        CLI_OPT_FLAG("--sightlines", o.sightlines, "every pair by its sightline, bare earth too, without the "
                     "bare-earth sweep (slower; the same maps)"),
        CLI_OPT_TEXT("--season", "S", season, CLI_HELP_SEASON),
        CLI_OPT_WHOLE("--threads", "N", bo.threads, 1, 1024, "threads for every phase (default: one per core, "
                      "shared out between the ranks of an MPI job on one machine); the maps do not depend on it"),
        CLI_OPTS_SCENE_COMMON(bo),
    };
    const cli_command_spec spec = {"ztv", "SCENE", ztv_about, "options (each overrides the scene's ztv: key of the "
                                   "same name):", options, sizeof options / sizeof *options, ztv_epilogue,
                                   cli_operand_scene, &scene_path};
    int parsed = cli_options_parse(&spec, argc, argv);
    if (parsed) return cli_options_status(parsed);
    o.threads = bo.threads;
    bo.analysis = !refined, bo.detail_at_development = refined;
    if (!o.threads) o.threads = bo.threads = m->threads;
    if (m->rank) bo.quiet = 1;
    o.quiet = bo.quiet;

    err_buf err = {{0}};
    cli_scene cs;
    cli_parts parts;
    cli_parts_of(&parts, m);
    cli_scene_use use = {.season = season, .no_camera = 1, .check_outputs = 1}; /* the folder's files */
    int rc = cli_scene_open(&cs, "ztv", scene_path, &use, &bo);
    if (!rc && ztv_study_run(cs.sf, cs.scene, &o, &parts.parts, &cs.times, &err)) rc = cli_parts_fail(&parts, &err);
    if (!rc && !m->rank) printf("%s\n", o.dir);
    cli_scene_close(&cs);
    return rc;
}

int cmd_ztv(int argc, char **argv)
{
    cli_mpi m;
    int rc = cli_mpi_begin(&m, "ztv", argc, argv);
    if (!rc) rc = ztv_run(&m, argc, argv);
    return cli_mpi_end(&m, rc);
}
