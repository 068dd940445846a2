/* cmd_montage.c — `sylva montage SCENE -o DIR`: the scene's development rendered into its
 * photograph with the camera matched to control points (montage/montage_run.h,
 * docs/photomontage.md). */
#include <stdio.h>
#include <string.h>

#include "cli/cli_args.h"
#include "cli/cli_outputs.h"
#include "cli/cli_scene.h"
#include "cli/cli_status.h"
#include "cli/commands.h"
#include "montage/montage_run.h"

static void montage_usage(FILE *out)
{
    fprintf(out,
            "usage: sylva montage SCENE -o DIR [options]\n"
            "Renders SCENE's development (the objects marked development: true) into the photograph\n"
            "of its photo: section: the camera matched to the control points, the terrain and the\n"
            "trees in front of the development hiding it, its shadows darkening the photograph.\n"
            "Writes into DIR (created when missing): montage.png and montage.exr, mask.png (the\n"
            "development's coverage), existing.png (the photograph as it is), wireline.png (the\n"
            "development's outline and edges over the photograph) and the verification sheet\n"
            "(sheet.html, sheet.png). See docs/photomontage.md.\n\n"
            "options:\n"
            "  -o, --output DIR        folder for the files (required)\n"
            "  --photo IMG             the photograph (default: photo: file)\n"
            "  --control-points FILE   the control points (default: photo: control_points)\n"
            "  --spp N                 samples per pixel (default: the scene's)\n"
            "  --threads N             threads for every phase (default: one per core)\n"
            "  --season S              the plants on season S (spring, summer, autumn, winter)\n"
            "                          or date YYYY-MM-DD, instead of the scene's season: key\n"
            "  -q, --quiet             no progress or information lines (warnings\n"
            "                          and errors still print)\n"
            "  --allow-gdal-virtual    let the scene name GDAL virtual paths, URLs and connection\n"
            "                          strings (these may reach the network; refused otherwise)\n"
            "  -v, --verbose           plugin debug messages\n"
            "  -h, --help              this text\n\n"
            "exit status: 0 done, 1 usage, 2 bad scene, photograph or control points (or points\n"
            "that cannot fix the camera), 3 output not written, 4 out of memory or internal error\n");
}

int cmd_montage(int argc, char **argv)
{
    const char *scene_path = NULL, *season = NULL;
    montage_options mo = {0};
    build_options bo = {0};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *val = i + 1 < argc ? argv[i + 1] : NULL;
        uint64_t v;
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            montage_usage(stdout);
            return EXIT_OK;
        } else if (!strcmp(a, "-o") || !strcmp(a, "--output")) {
            if (!val) goto missing;
            mo.dir = val, i++;
        } else if (!strcmp(a, "--photo")) {
            if (!val) goto missing;
            mo.photo = val, i++;
        } else if (!strcmp(a, "--control-points")) {
            if (!val) goto missing;
            mo.points = val, i++;
        } else if (!strcmp(a, "--spp")) {
            if (!val || cli_parse_u64("montage", a, val, 1, 1u << 20, &v)) return EXIT_USAGE;
            mo.spp = (uint32_t)v, i++;
        } else if (!strcmp(a, "--threads")) {
            if (!val || cli_parse_u64("montage", a, val, 1, 1024, &v)) return EXIT_USAGE;
            mo.threads = bo.threads = (unsigned)v, i++;
        } else if (!strcmp(a, "--season")) {
            if (!val) goto missing;
            season = val, i++;
        } else if (!strcmp(a, "-q") || !strcmp(a, "--quiet")) {
            mo.quiet = bo.quiet = 1;
        } else if (!strcmp(a, "-v") || !strcmp(a, "--verbose")) {
            bo.verbose = 1;
        } else if (cli_scene_argument("montage", a, &scene_path)) {
            return EXIT_USAGE;
        }
        continue;
    missing:
        fprintf(stderr, "sylva montage: %s needs a value\n", a);
        return EXIT_USAGE;
    }
    if (!scene_path || !mo.dir) {
        montage_usage(stderr);
        return EXIT_USAGE;
    }
    err_buf err = {{0}};
    cli_scene cs;
    montage_report rep = {0};
    int rc = cli_scene_open(&cs, "montage", scene_path, NULL, season, &bo);
    cli_file inputs[] = {{mo.photo, "--photo"}, {mo.points, "--control-points"}};
    if (!rc) rc = cli_outputs_check("montage", cs.sf, inputs, 2, NULL, 0);
    if (!rc && cli_make_folder(mo.dir, &err)) rc = cli_fail("montage", &err, ERR_OUTPUT);
    if (!rc && montage_run(cs.scene, cs.sf, &mo, &rep, &err)) rc = cli_fail("montage", &err, ERR_INPUT);
    if (!rc) printf("%s\n", mo.dir);
    montage_report_free(&rep);
    cli_scene_close(&cs);
    return rc;
}
