/* cmd_probe.c — `sylva probe SCENE E N`: the ground at one point of a scene (height, slope,
 * aspect, water) and what stands there (plants within a radius, objects over it), read from the
 * built scene (scene/scene_probe.h). With a site, the point and every position printed are map
 * coordinates (local = map - site origin); without one, local metres. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli_args.h"
#include "cli/cli_scene.h"
#include "cli/cli_status.h"
#include "cli/commands.h"
#include "site/scene_probe.h"

#define PROBE_LIST_MAX 20 /* plants listed one by one; the rest are counted */

static void probe_usage(FILE *out)
{
    fprintf(out,
            "usage: sylva probe SCENE E N [options]\n"
            "Prints what is at one point of SCENE's ground: the terrain's height, slope and aspect\n"
            "there, whether water covers it, the plants standing within a radius (species, height,\n"
            "distance, position; nearest first) and the objects whose footprint covers it (with\n"
            "their top above the point). The scene is built as for rendering (plugins run).\n\n"
            "E N are map coordinates in the site's CRS when the scene has a site (local = map -\n"
            "site origin), local metres otherwise; positions and heights are printed the same way.\n\n"
            "options:\n"
            "  --local             E N are local metres even when the scene has a site\n"
            "  --radius R          plants within R metres of the point (default 10)\n"
            "  -q, --quiet         no progress or information lines (warnings\n"
            "                      and errors still print)\n"
            "  --allow-gdal-virtual let the scene name GDAL virtual paths, URLs and connection\n"
            "                      strings (these may reach the network; refused otherwise)\n"
            "  -v, --verbose       plugin debug messages\n"
            "  -h, --help          this text\n\n"
            "exit status: 0 done, 1 usage, 2 bad scene, plugin failure, no terrain or a point off\n"
            "the terrain, 4 out of memory or internal error\n");
}

/* A finite number, the whole of s. */
static int parse_number(const char *s, double *out)
{
    char *end;
    double v = strtod(s, &end);
    if (end == s || *end || !isfinite(v)) return -1;
    *out = v;
    return 0;
}

static const char *compass_name(double deg)
{
    static const char *const names[] = {"north", "north-east", "east", "south-east",
                                        "south", "south-west", "west", "north-west"};
    return names[(int)floor(fmod(deg + 22.5, 360.0) / 45.0) % 8];
}

static void print_result(const scene *sc, const probe_result *r, const double shift[3], const char *frame,
                         double radius)
{
    printf("ground      %.3f m\n", r->ground + shift[2]);
    printf("slope       %.2f deg\n", r->slope_deg);
    if (isnan(r->aspect_deg)) printf("aspect      none (level ground)\n");
    else printf("aspect      %.1f deg (falls toward the %s)\n", r->aspect_deg, compass_name(r->aspect_deg));
    if (r->water)
        printf("water       yes: level %.3f m, %.3f m deep\n", r->water_level + shift[2], r->water_depth);
    else
        printf("water       no\n");
    printf("plants      %u within %g m\n", r->n_plants, radius);
    if (r->n_plants)
        printf("  %-24s %10s %10s %14s %14s %10s   (%s)\n", "species", "height_m", "distance_m", "x", "y", "z", frame);
    for (uint32_t i = 0; i < r->n_plants && i < PROBE_LIST_MAX; i++) {
        const probe_plant *p = &r->plants[i];
        printf("  %-24s %10.2f %10.2f %14.3f %14.3f %10.3f\n", sc->species[p->species].name, p->height, p->distance,
               p->position[0] + shift[0], p->position[1] + shift[1], p->position[2] + shift[2]);
    }
    if (r->n_plants > PROBE_LIST_MAX) printf("  ... and %u more\n", r->n_plants - PROBE_LIST_MAX);
    printf("objects     %u over the point\n", r->n_objects);
    for (uint32_t i = 0; i < r->n_objects; i++) {
        const probe_object *o = &r->objects[i];
        printf("  %-24s top %.3f m, %.3f m above the ground\n", sc->objects[o->object].name, o->top + shift[2],
               o->top - r->ground);
    }
}

int cmd_probe(int argc, char **argv)
{
    const char *scene_path = NULL, *coord[2] = {NULL, NULL};
    int local = 0, n_coord = 0;
    double radius = 10.0, at[2];
    build_options bo = {.analysis = 1}; /* the ground as surveyed, whatever the camera */
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *val = i + 1 < argc ? argv[i + 1] : NULL;
        double v;
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            probe_usage(stdout);
            return EXIT_OK;
        } else if (!strcmp(a, "--local")) {
            local = 1;
        } else if (!strcmp(a, "--radius")) {
            if (!val || parse_number(val, &radius) || radius < 0 || radius > 1e6) {
                fprintf(stderr, "sylva probe: --radius expects metres from 0 to 1e6, got '%s'\n", val ? val : "");
                return EXIT_USAGE;
            }
            i++;
        } else if (!strcmp(a, "-q") || !strcmp(a, "--quiet")) {
            bo.quiet = 1;
        } else if (!strcmp(a, "-v") || !strcmp(a, "--verbose")) {
            bo.verbose = 1;
        } else if (scene_path && (a[0] != '-' || !parse_number(a, &v))) {
            /* after the scene: the coordinates (negative ones too) */
            if (n_coord == 2) {
                fprintf(stderr, "sylva probe: one point only (E N); '%s' is extra\n", a);
                return EXIT_USAGE;
            }
            coord[n_coord++] = a;
        } else if (cli_scene_argument("probe", a, &scene_path)) {
            return EXIT_USAGE;
        }
    }
    if (!scene_path || n_coord < 2) {
        probe_usage(stderr);
        return EXIT_USAGE;
    }
    for (int k = 0; k < 2; k++)
        if (parse_number(coord[k], &at[k])) {
            fprintf(stderr, "sylva probe: %s expects a number (metres), got '%s'\n", k ? "N" : "E", coord[k]);
            return EXIT_USAGE;
        }

    cli_scene cs;
    probe_result r = {0};
    int rc = cli_scene_open(&cs, "probe", scene_path, NULL, NULL, &bo);
    if (rc) goto done;
    const site_settings *site = &cs.sf->site;
    int mapped = site->crs_wkt != NULL;
    /* Map coordinates in and out with a site: shift = the site origin; local metres otherwise. */
    double shift[3] = {0, 0, 0};
    if (mapped) memcpy(shift, site->origin, sizeof shift);
    double x = local ? at[0] : at[0] - shift[0], y = local ? at[1] : at[1] - shift[1];
    const char *frame = mapped ? (site->crs_name ? site->crs_name : "map coordinates") : "local metres";
    err_buf err = {{0}};
    if (scene_probe(cs.scene, x, y, radius, &r, &err)) {
        if (mapped) err_prefix(&err, "map point E %.3f N %.3f: ", x + shift[0], y + shift[1]);
        rc = cli_fail("probe", &err, ERR_INPUT);
        goto done;
    }
    if (mapped)
        printf("point       E %.3f N %.3f (%s) = local x %.3f y %.3f\n", x + shift[0], y + shift[1], frame, x, y);
    else
        printf("point       x %.3f y %.3f (local metres)\n", x, y);
    print_result(cs.scene, &r, shift, frame, radius);
done:
    probe_result_free(&r);
    cli_scene_close(&cs);
    return rc;
}
