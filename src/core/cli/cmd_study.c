/* cmd_study.c — `sylva study SCENE -o DIR`: every viewpoint's products (the view without the
 * development, with it, and its wireline) in every frame asked for, and the study's ZTV, from one
 * build of the scene (study/study_run.h, docs/study.md). Under mpirun each rank builds the scene and renders whole
 * images: every N-th viewpoint-frame to render. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/cli_mpi.h"
#include "cli/cli_options.h"
#include "cli/cli_outputs.h"
#include "cli/cli_parts.h"
#include "cli/cli_scene.h"
#include "cli/cli_status.h"
#include "cli/commands.h"
#include "scene/scene_surveyed.h"
#include "study/study_run.h"
#include "ztv/ztv_study.h"

static const char study_about[] =
    "Renders SCENE's viewpoints for a visual-impact study from one build of the scene: for\n"
    "each viewpoint (its viewpoints: section and the study's points file) and frame (single:\n"
    "50 mm on a full-frame sensor; planar_53; cylindrical_90), the existing view (without\n"
    "the development), the proposed view (with it) and the wireline (the development's\n"
    "outline over the existing view), as DIR/VIEWPOINT/PRODUCT_FRAME.png and .exr with a\n"
    ".manifest record each; and when asked, the sheet (the three views on one printed page with\n"
    "the viewpoint's facts and a location map) as DIR/VIEWPOINT/sheet_FRAME.pdf and .png. A rerun keeps every product whose files are there and whose record\n"
    "matches, so an interrupted study goes on where it stopped. The proposed view is byte for\n"
    "byte `sylva render --viewpoint NAME --size WxH` of the same viewpoint, with the ground\n"
    "refined around the development rather than the camera. With a ztv: section (or the\n"
    "product ztv) the study also maps its ZTV once, from the same build on the ground as\n"
    "surveyed, into DIR/ztv/ (sylva ztv's files and GeoPackage); last it writes DIR/index.html,\n"
    "the viewpoints on the map, each linked to its sheets and images. See docs/study.md.\n";

static const char study_epilogue[] =
    "Under MPI (`mpirun -np N sylva study ...`, in a build with SYLVA_MPI), every rank builds\n"
    "the scene itself and renders every N-th viewpoint-frame left to render, writing its\n"
    "files itself. Only rank 0 prints. See docs/mpi.md.\n\n"
    "exit status: 0 done, 1 usage, 2 bad scene, viewpoint or plugin failure, 3 output not\n"
    "written, 4 out of memory or internal error\n";

/* The study's last lines: what was written and kept, and where the time went (rank 0's share
 * of an MPI job's). */
static void report(const study_report *r, int ranks)
{
    char share[48] = "";
    if (ranks > 1) snprintf(share, sizeof share, " (rank 0 of %d)", ranks);
    fprintf(stderr, "study%s: %u product%s written, %u up to date; %u scene build%s, %u frame%s rendered; total "
            "%.2fs (scene %.2fs)\n", share, r->rendered, r->rendered == 1 ? "" : "s", r->kept, r->builds,
            r->builds == 1 ? "" : "s", r->renders, r->renders == 1 ? "" : "s", r->seconds, r->build_seconds);
    if (r->ztv) fprintf(stderr, "study: the ZTV %s\n", r->ztv == 1 ? "mapped into ztv/" : "up to date in ztv/");
    if (r->renders) phase_times_print(&r->times, stderr);
}

/* The study's visibility map (study/study_ztv.h): `sylva ztv`'s on the scene the study built, traced
 * on the ground as surveyed, as `sylva ztv` traces it, not the ground refined for the views. */
static int study_map_ztv(void *user, const scene_file *sf, const scene *s, const study_views *views, const char *dir,
                         const run_parts *parts, phase_times *times, err_buf *err)
{
    const study_options *o = user;
    scene_surveyed surveyed; /* the same scene on the DTM as surveyed, its plants standing on it */
    if (scene_surveyed_view(s, &surveyed, err)) return -1;
    ztv_study_options zo = {.dir = dir, .radius = NAN, .cell = NAN, .eye = NAN, .screening = -1,
                            .threads = o->build.threads, .quiet = o->build.quiet, .views = views->views,
                            .n_views = views->n};
    phase_times own = {0}; /* the map's phases, printed as its own and added to the study's */
    int rc = ztv_study_run(sf, &surveyed.view, &zo, parts, &own, err);
    for (int p = 0; p < PHASE_COUNT; p++) phase_add(times, (job_phase)p, own.seconds[p]);
    scene_surveyed_free(&surveyed);
    return rc;
}

/* One study of sf into o->dir. */
static int study_once(scene_file *sf, const plugin_registry *reg, const study_options *o, cli_parts *parts,
                      const cli_mpi *m)
{
    err_buf err = {{0}};
    study_report rep;
    if (study_run(sf, reg, o, &parts->parts, &rep, &err)) return cli_parts_fail(parts, &err);
    if (!o->build.quiet) report(&rep, m->ranks);
    return EXIT_OK;
}

/* A study of a planting plan: one study at each of study.years, each in its season, into
 * DIR/year_N_SEASON. */
static int study_years(scene_file *sf, const plugin_registry *reg, const study_options *o, cli_parts *parts,
                       const cli_mpi *m)
{
    if (!m->rank && mkdir(o->dir, 0777) && errno != EEXIST)
        return cli_failf("study", ERR_OUTPUT, "cannot make the folder %s: %s", o->dir, strerror(errno));
    int rc = EXIT_OK;
    for (uint32_t y = 0; y < sf->study.n_years && !rc; y++) {
        const study_year *year = &sf->study.years[y];
        char dir[4200];
        snprintf(dir, sizeof dir, "%s/year_%g_%s", o->dir, year->years, year->season);
        study_options at = *o;
        at.dir = dir;
        at.build.planting_shown = 1, at.build.planting_years = year->years;
        sf->season.day = year->day, sf->season.text = year->season;
        if (!o->build.quiet) fprintf(stderr, "study: year %g after planting, %s\n", year->years, year->season);
        rc = study_once(sf, reg, &at, parts, m);
    }
    return rc;
}

static int study_main(cli_mpi *m, int argc, char **argv)
{
    const char *scene_path = NULL, *season = NULL, *points = NULL, *points_layer = NULL;
    study_options o = {.ztv = {.map = study_map_ztv}};
    o.ztv.user = &o;
    uint32_t width = 0;
    const cli_option options[] = {
        {.names = "-o, --output", .type = CLI_PATH, .value = "DIR", .target = &o.dir, .flags = CLI_REQUIRED,
         .help = "folder for the study (created when missing): a folder per viewpoint"},
        CLI_OPT_TEXT("--viewpoints", "LIST", o.names.viewpoints, "the viewpoints to render, in rank order (names "
                     "separated by commas; default: the study's viewpoints, else every one and every point)"),
        CLI_OPT_PATH("--points", "FILE", points, "viewpoints from a file of points in place of study: points (a CSV "
                     "with id, easting and northing or longitude and latitude, height_above_ground, heading; or a "
                     "point layer: GeoPackage, Shapefile, GeoJSON)"),
        CLI_OPT_TEXT("--points-layer", "NAME", points_layer, "the layer of --points holding the viewpoints"),
        CLI_OPT_TEXT("--only", "LIST", o.names.only, "render only these viewpoints of the study (the rest are "
                     "left as they are)"),
        CLI_OPT_TEXT("--rank", "LIST", o.names.rank, "render these viewpoints first, in this order"),
        CLI_OPT_TEXT("--products", "LIST", o.products, "existing, proposed, wireline, sheet, ztv (default: the "
                     "study's, else the first three, and ztv when the scene has a ztv: section)"),
        CLI_OPT_TEXT("--frames", "LIST", o.frames, "single, planar_53, cylindrical_90 (default: the study's, else "
                     "single)"),
        CLI_OPT_SIZE("--size", o.size[0], o.size[1], "every frame at WxH pixels (overrides study: size and "
                     "print_width)"),
        CLI_OPT_WHOLE("--width", "N", width, 1, 16384, "frames N pixels wide, each as high as its page (single 3:2, "
                      "planar_53 and cylindrical_90 820:260)"),
        CLI_OPT_NUMBER("--print-width", "MM", "millimetres", o.print_width_mm, 0, 10000, CLI_OPEN_LOW,
                       "frames print_width / 25.4 * dpi pixels wide, each as high as its page"),
        CLI_OPT_NUMBER("--dpi", "N", "pixels per inch", o.dpi, 0, 10000, CLI_OPEN_LOW, "pixels per inch of the "
                       "print and of the sheets (default: the study's, else 300)"),
        CLI_OPT_WHOLE("--spp", "N", o.spp, 1, 1u << 20, "samples per pixel (default: the study's, else image.spp)"),
        CLI_OPT_FLAG("--force", o.force, "render every product, even those up to date"),
        CLI_OPT_TEXT("--season", "S", season, CLI_HELP_SEASON),
        CLI_OPT_WHOLE("--threads", "N", o.build.threads, 1, 1024, "threads for every phase (default: one per "
                      "core); the images do not depend on it"),
        CLI_OPTS_SCENE_COMMON(o.build),
    };
    const cli_command_spec spec = {"study", "SCENE", study_about, "options (each overrides the scene's study: key "
                                   "of the same name):", options, sizeof options / sizeof *options, study_epilogue,
                                   cli_operand_scene, &scene_path};
    int parsed = cli_options_parse(&spec, argc, argv);
    if (parsed) return cli_options_status(parsed);
    if (points_layer && !points) {
        fprintf(stderr, "sylva study: --points-layer names a layer of --points, which is not given\n");
        return EXIT_USAGE;
    }
    if (width && o.size[0]) {
        fprintf(stderr, "sylva study: give --size or --width, not both\n");
        return EXIT_USAGE;
    }
    if (width) o.size[0] = width, o.size[1] = 0;
    if (!o.build.threads) o.build.threads = m->threads;
    if (m->rank) o.build.quiet = 1;

    err_buf err = {{0}};
    cli_scene cs;
    cli_parts parts;
    cli_parts_of(&parts, m);
    cli_file inputs[] = {{points, "--points"}};
    cli_scene_use use = {.season = season, .no_camera = 1, .no_build = 1, .check_outputs = 1, .inputs = inputs,
                         .n_inputs = points ? 1 : 0};
    int rc = cli_scene_open(&cs, "study", scene_path, &use, &o.build);
    if (!rc && points && scene_file_read_points(cs.sf, points, points_layer, &err)) rc = cli_fail(NULL, &err, ERR_INPUT);
    if (!rc && cs.sf->study.n_years) rc = study_years(cs.sf, cs.reg, &o, &parts, m);
    else if (!rc) rc = study_once(cs.sf, cs.reg, &o, &parts, m);
    if (!rc && !m->rank) printf("%s\n", o.dir);
    cli_scene_close(&cs);
    return rc;
}

int cmd_study(int argc, char **argv)
{
    cli_mpi m;
    int rc = cli_mpi_begin(&m, "study", argc, argv);
    if (!rc) rc = study_main(&m, argc, argv);
    return cli_mpi_end(&m, rc);
}
