/* cmd_probe.c — `sylva probe SCENE E N`: the ground at one point of a scene (height, slope,
 * aspect, water) and what stands there (plants within a radius, objects over it), read from the
 * built scene (site/scene_probe.h). With a site, the point and every position printed are map
 * coordinates (local = map - site origin); without one, local metres. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli_args.h"
#include "cli/cli_options.h"
#include "cli/cli_scene.h"
#include "cli/cli_status.h"
#include "cli/commands.h"
#include "site/scene_probe.h"

#define PROBE_LIST_MAX 20 /* plants listed one by one; the rest are counted */

static const char probe_about[] =
    "Prints what is at one point of SCENE's ground: the terrain's height, slope and aspect\n"
    "there, whether water covers it, the plants standing within a radius (species, height,\n"
    "distance, position; nearest first) and the objects whose footprint covers it (with\n"
    "their top above the point), and its land-cover class (code, name, kind) when the scene\n"
    "has a landcover: section. The scene is built as for rendering (plugins run).\n\n"
    "E N are map coordinates in the site's CRS when the scene has a site (local = map -\n"
    "site origin), local metres otherwise; positions and heights are printed the same way.\n";

static const char probe_epilogue[] =
    "exit status: 0 done, 1 usage, 2 bad scene, plugin failure, no terrain or a point off\n"
    "the terrain, 4 out of memory or internal error\n";

/* The operands: the scene, then E and N (negative ones too). */
typedef struct probe_operands {
    const char *scene_path, *coord[2];
    int n_coord;
} probe_operands;

static int parse_number(const char *s, double *out);

static int probe_operand(void *ctx, const char *cmd, const char *a)
{
    probe_operands *p = ctx;
    double v;
    if (!a) return p->scene_path && p->n_coord == 2 ? 0 : -1;
    if (!p->scene_path || (a[0] == '-' && parse_number(a, &v))) return cli_scene_argument(cmd, a, &p->scene_path);
    if (p->n_coord == 2) {
        fprintf(stderr, "sylva %s: one point only (E N); '%s' is extra\n", cmd, a);
        return -1;
    }
    p->coord[p->n_coord++] = a;
    return 0;
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

/* The land-cover class at the point: its code, name and kind (only when the scene has land cover). */
static void print_land_cover(const scene *sc, const probe_result *r)
{
    const land_cover *lc = sc->land_cover;
    if (!lc) return;
    if (r->land_class < 0) {
        printf("landcover   no data (%s has no class here)\n", lc->source);
        return;
    }
    const land_class *c = &lc->classes[r->land_class];
    printf("landcover   %lld %s (%s; legend %s)\n", (long long)c->code, c->name, land_kind_names[c->kind], lc->legend);
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
    print_land_cover(sc, r);
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
    int local = 0;
    double radius = 10.0, at[2];
    build_options bo = {.analysis = 1}; /* the ground as surveyed, whatever the camera */
    const cli_option options[] = {
        CLI_OPT_FLAG("--local", local, "E N are local metres even when the scene has a site"),
        CLI_OPT_NUMBER("--radius", "R", "metres", radius, 0, 1e6, 0, "plants within R metres of the point (default 10)"),
        CLI_OPT_YEAR(bo),
        CLI_OPTS_SCENE_COMMON(bo),
    };
    probe_operands ops = {0};
    const cli_command_spec spec = {"probe", "SCENE E N", probe_about, NULL, options, sizeof options / sizeof *options,
                                   probe_epilogue, probe_operand, &ops};
    int parsed = cli_options_parse(&spec, argc, argv);
    if (parsed) return cli_options_status(parsed);
    const char *scene_path = ops.scene_path, *const *coord = ops.coord;
    for (int k = 0; k < 2; k++)
        if (parse_number(coord[k], &at[k])) {
            fprintf(stderr, "sylva probe: %s expects a number (metres), got '%s'\n", k ? "N" : "E", coord[k]);
            return EXIT_USAGE;
        }

    cli_scene cs;
    probe_result r = {0};
    int rc = cli_scene_open(&cs, "probe", scene_path, &(cli_scene_use){.no_camera = 1}, &bo);
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
