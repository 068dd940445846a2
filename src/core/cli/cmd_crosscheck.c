/* cmd_crosscheck.c — `sylva crosscheck SCENE`: render the scene in sylva's verification mode and
 * with POV-Ray from its export, compare, write the report; the exit status says whether the
 * thresholds hold. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli_args.h"
#include "cli/cli_outputs.h"
#include "cli/cli_scene.h"
#include "cli/cli_status.h"
#include "cli/commands.h"
#include "crosscheck/crosscheck.h"

enum { EXIT_DISAGREE = 5 }; /* both renders compared; a threshold does not hold */

static void crosscheck_usage(FILE *out)
{
    crosscheck_thresholds t;
    crosscheck_default_thresholds(&t);
    fprintf(out,
            "usage: sylva crosscheck SCENE [options]\n"
            "Renders SCENE in sylva's verification mode and with POV-Ray 3.7 from its export, at the\n"
            "same size with the same camera samples (pixel centre plus a regular grid, no jitter),\n"
            "compares the two in linear float overall and per class (terrain, bark, leaves,\n"
            "objects, sky) and writes DIR/report.html and DIR/metrics.json with both pictures, a\n"
            "difference heatmap and both renderers' timing (see docs/crosscheck.md). POV-Ray cannot\n"
            "bend rays: a scene with earth.curvature on is compared on a flat Earth, and the report\n"
            "says so.\n\n"
            "options:\n"
            "  -o, --output DIR     output folder (default: crosscheck-<scene name>)\n"
            "  --size WxH           image size (default: the scene's)\n"
            "  --spp N              samples per pixel, rounded down to a square (default: the scene's)\n"
            "  --threads N          threads for the scene build and both renderers (default: one\n"
            "                       per core)\n"
            "  --povray PATH        POV-Ray's executable (default: $SYLVA_POVRAY, else povray)\n"
            "  --pov FILE.pov       compare against this POV-Ray scene instead of exporting SCENE\n"
            "                       (an export for the same size, e.g. edited by hand)\n"
            "  --min-coverage F     coverage agreement at least F (default %g)\n"
            "  --max-mae X          mean absolute error at most X (default %g)\n"
            "  --over-error X       a pixel is over when a channel differs by more than X (default %g)\n"
            "  --max-over F         share of over pixels at most F (default %g)\n"
            "  --max-class-mae X    MAE within each class covering >= %g of the picture (default %g)\n"
            "  --viewpoint NAME    the view from the scene's viewpoint NAME (its viewpoints:\n"
            "                      section) instead of its camera\n"
            "  --season S           the plants on season S (spring, summer, autumn, winter) or\n"
            "                       date YYYY-MM-DD, instead of the scene's season: key\n"
            "  -q, --quiet          no progress or information lines (warnings\n"
            "                       and errors still print)\n"
            "  --allow-gdal-virtual let the scene name GDAL virtual paths, URLs and connection\n"
            "                      strings (these may reach the network; refused otherwise)\n"
            "  -v, --verbose        plugin debug messages\n"
            "  -h, --help           this text\n\n"
            "Prints the verdict and the report's path.\n"
            "exit status: 0 the renders agree within the thresholds, 5 they do not, 1 usage,\n"
            "2 bad scene or plugin failure, 3 output not written, 4 POV-Ray missing or failing,\n"
            "out of memory or internal error\n",
            t.min_coverage_agreement, t.max_mae, t.over_error, t.max_over_fraction, t.min_class_share, t.max_class_mae);
}

/* Parses a real in [lo, hi]; prints a message naming the option when bad. */
static int parse_real(const char *opt, const char *s, double lo, double hi, double *out)
{
    char *end;
    double v = s ? strtod(s, &end) : 0.0;
    if (!s || end == s || *end || !(v >= lo && v <= hi)) {
        fprintf(stderr, "sylva crosscheck: %s needs a number from %g to %g, got '%s'\n", opt, lo, hi, s ? s : "");
        return -1;
    }
    *out = v;
    return 0;
}

int cmd_crosscheck(int argc, char **argv)
{
    const char *viewpoint = NULL, *season = NULL;
    const char *scene_path = NULL, *out = NULL;
    crosscheck_options co = {0};
    crosscheck_default_thresholds(&co.thresholds);
    crosscheck_thresholds *t = &co.thresholds;
    build_options bo = {0};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *val = i + 1 < argc ? argv[i + 1] : NULL;
        uint64_t v;
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            crosscheck_usage(stdout);
            return EXIT_OK;
        } else if (!strcmp(a, "-o") || !strcmp(a, "--output")) {
            if (!val) goto missing;
            out = val, i++;
        } else if (!strcmp(a, "--size")) {
            if (!val || cli_parse_size("crosscheck", a, val, &co.width, &co.height)) return EXIT_USAGE;
            i++;
        } else if (!strcmp(a, "--spp")) {
            if (!val || cli_parse_u64("crosscheck", a, val, 1, 1u << 16, &v)) return EXIT_USAGE;
            co.spp = (uint32_t)v, i++;
        } else if (!strcmp(a, "--threads")) {
            if (!val || cli_parse_u64("crosscheck", a, val, 1, 1024, &v)) return EXIT_USAGE;
            co.threads = bo.threads = (unsigned)v, i++;
        } else if (!strcmp(a, "--povray")) {
            if (!val) goto missing;
            co.povray = val, i++;
        } else if (!strcmp(a, "--pov")) {
            if (!val) goto missing;
            co.pov_scene = val, i++;
        } else if (!strcmp(a, "--min-coverage")) {
            if (parse_real(a, val, 0, 1, &t->min_coverage_agreement)) return EXIT_USAGE;
            i++;
        } else if (!strcmp(a, "--max-mae")) {
            if (parse_real(a, val, 0, 1e30, &t->max_mae)) return EXIT_USAGE;
            i++;
        } else if (!strcmp(a, "--over-error")) {
            if (parse_real(a, val, 0, 1e30, &t->over_error)) return EXIT_USAGE;
            i++;
        } else if (!strcmp(a, "--max-over")) {
            if (parse_real(a, val, 0, 1, &t->max_over_fraction)) return EXIT_USAGE;
            i++;
        } else if (!strcmp(a, "--max-class-mae")) {
            if (parse_real(a, val, 0, 1e30, &t->max_class_mae)) return EXIT_USAGE;
            i++;
        } else if (!strcmp(a, "--viewpoint")) {
            if (!val) goto missing;
            viewpoint = val, i++;
        } else if (!strcmp(a, "--season")) {
            if (!val) goto missing;
            season = val, i++;
        } else if (!strcmp(a, "-q") || !strcmp(a, "--quiet")) {
            co.quiet = bo.quiet = 1;
        } else if (!strcmp(a, "-v") || !strcmp(a, "--verbose")) {
            bo.verbose = 1;
        } else if (cli_scene_argument("crosscheck", a, &scene_path)) {
            return EXIT_USAGE;
        }
        continue;
    missing:
        fprintf(stderr, "sylva crosscheck: %s needs a value\n", a);
        return EXIT_USAGE;
    }
    if (!scene_path) {
        crosscheck_usage(stderr);
        return EXIT_USAGE;
    }
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
    int rc = cli_scene_open(&cs, "crosscheck", scene_path, viewpoint, season, &bo);
    if (!rc) rc = cli_outputs_check("crosscheck", cs.sf, NULL, 0, NULL, 0); /* the folder's files */
    if (!rc) rc = cli_scene_ground_cover(&cs, "crosscheck", co.width, co.height, co.quiet);
    if (rc) goto done;
    const scene *sc = cs.scene;
    crosscheck_result *r = malloc(sizeof *r);
    if (!r) {
        rc = cli_failf("crosscheck", ERR_NOMEM, "out of memory");
        goto done;
    }
    if (sc->earth.curvature && !co.quiet)
        fprintf(stderr, "sylva crosscheck: note: POV-Ray cannot bend rays for the Earth's curvature "
                        "(earth.curvature is on); both renderers draw this scene on a flat Earth here\n");
    int status = crosscheck_run(sc, out, &co, r, &err);
    if (status) {
        rc = cli_fail("crosscheck", &err, status == CROSSCHECK_NOT_WRITTEN ? ERR_OUTPUT : ERR_INTERNAL);
    } else {
        printf("%s\n%s/report.html\n", r->verdict, out);
        rc = r->pass ? EXIT_OK : EXIT_DISAGREE;
    }
    free(r);
done:
    cli_scene_close(&cs);
    return rc;
}
