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
#include "ztv/ztv_years.h"

#include <errno.h>
#include <sys/stat.h>

#define ZTV_YEARS_MAX 64 /* years in one --years list */

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

/* "1,5,15,30" into years, increasing; -1 after printing why. */
static int parse_years(const char *text, double *years, uint32_t *n)
{
    *n = 0;
    for (const char *p = text; *p;) {
        char *end;
        errno = 0;
        double y = strtod(p, &end);
        if (end == p || errno || !(y >= 0 && y <= 10000) || (*n && y <= years[*n - 1]) || *n == ZTV_YEARS_MAX ||
            (*end && *end != ',')) {
            fprintf(stderr, "sylva ztv: --years '%s': give at most %u years since planting, increasing, between 0 "
                    "and 10000, separated by commas (1,5,15,30)\n", text, ZTV_YEARS_MAX);
            return -1;
        }
        years[(*n)++] = y;
        p = *end ? end + 1 : end;
    }
    if (!*n) {
        fprintf(stderr, "sylva ztv: --years: give the years since planting, separated by commas (1,5,15,30)\n");
        return -1;
    }
    return 0;
}

/* The kinds of file --products names, in ZTV_PRODUCT_* bit order (ztv/ztv_raster.h). */
static const char *const product_names[] = {"raster", "maps", "summary", "layers"};

/* "raster,summary" (or "all") into the ZTV_PRODUCT_* bits; -1 after printing why. */
static int parse_products(const char *text, unsigned *products)
{
    *products = 0;
    for (const char *p = text; *p;) {
        size_t len = strcspn(p, ",");
        unsigned bit = 0;
        if (len == 3 && !strncmp(p, "all", 3)) bit = ZTV_PRODUCTS_ALL;
        for (unsigned k = 0; k < sizeof product_names / sizeof *product_names && !bit; k++)
            if (strlen(product_names[k]) == len && !strncmp(p, product_names[k], len)) bit = 1u << k;
        if (!bit) {
            fprintf(stderr, "sylva ztv: --products '%s': '%.*s' is not a product; give a list of raster, maps, "
                    "summary, layers separated by commas, or all\n", text, (int)len, p);
            return -1;
        }
        *products |= bit;
        p += len;
        if (*p) p++;
    }
    if (!*products) {
        fprintf(stderr, "sylva ztv: --products: give a list of raster, maps, summary, layers separated by commas, "
                "or all\n");
        return -1;
    }
    return 0;
}

/* A map of bare earth or of the canopy surface traces no plant: its scene is built without them
 * (a woodland's ecology can be most of a run). arg: the command's ztv_study_options. */
static void build_for_map(const scene_file *sf, build_options *bo, const void *arg)
{
    const ztv_study_options *o = arg;
    int mode = o->screening >= 0 ? o->screening : (int)sf->ztv.screening;
    bo->no_plants = mode == ZTV_BARE || mode == ZTV_CANOPY;
    if (bo->no_plants && !bo->quiet)
        fprintf(stderr, "ztv: %s: the scene's plants are not built\n",
                mode == ZTV_BARE ? "bare earth only" : "screened by the canopy surface");
}

/* One map into dir: the scene built (at the planting year bo says) and traced. */
static int ztv_one(cli_mpi *m, const char *scene_path, const cli_scene_use *use, const build_options *bo,
                   ztv_study_options o, const char *dir)
{
    err_buf err = {{0}};
    cli_scene cs;
    cli_parts parts;
    cli_parts_of(&parts, m);
    o.dir = dir;
    int rc = cli_scene_open(&cs, "ztv", scene_path, use, bo);
    if (!rc && ztv_study_run(cs.sf, cs.scene, &o, &parts.parts, &cs.times, &err)) rc = cli_parts_fail(&parts, &err);
    cli_scene_close(&cs);
    return rc;
}

/* --years: a map before the plan (DIR/before) and one each year (DIR/year_N), then what the planting
 * hides in each year and the visible area against the years (ztv_years.h). */
static int ztv_years_run(cli_mpi *m, const char *scene_path, const cli_scene_use *use, build_options bo,
                         const ztv_study_options *o, const char *list)
{
    double years[ZTV_YEARS_MAX];
    uint32_t n;
    if (parse_years(list, years, &n)) return EXIT_USAGE;
    if (!m->rank && mkdir(o->dir, 0777) && errno != EEXIST)
        return cli_failf("ztv", ERR_OUTPUT, "cannot make the folder %s: %s", o->dir, strerror(errno));
    ztv_year_row rows[ZTV_YEARS_MAX + 1];
    static char dirs[ZTV_YEARS_MAX + 1][4200];
    int rc = EXIT_OK;
    for (uint32_t r = 0; r <= n && !rc; r++) {
        rows[r] = (ztv_year_row){.year = r ? years[r - 1] : -1, .dir = dirs[r]};
        if (r) snprintf(dirs[r], sizeof dirs[r], "%s/year_%g", o->dir, years[r - 1]);
        else snprintf(dirs[r], sizeof dirs[r], "%s/before", o->dir);
        bo.planting_shown = r > 0, bo.planting_years = r ? years[r - 1] : 0;
        ztv_study_options year_o = *o;
        if (r) year_o.planting_before = dirs[0], year_o.planting_year = years[r - 1];
        rc = ztv_one(m, scene_path, use, &bo, year_o, dirs[r]);
    }
    err_buf err = {{0}};
    const char *mode = o->screening == ZTV_ALL ? "all" : "vegetation";
    if (!rc && !m->rank && ztv_years_write(o->dir, mode, rows, n + 1, &err)) rc = cli_fail("ztv", &err, ERR_OUTPUT);
    for (uint32_t r = 0; !rc && !m->rank && r <= n; r++) {
        if (r) printf("year %g: seen from %.6g km2, hidden by the planting from %.6g km2 (partly from %.6g km2)\n",
                      rows[r].year, rows[r].visible_km2, rows[r].hidden_km2, rows[r].partly_km2);
        else printf("before the planting: seen from %.6g km2\n", rows[r].visible_km2);
    }
    if (!rc && !m->rank) printf("%s\n", o->dir);
    return rc;
}

static int ztv_run(cli_mpi *m, int argc, char **argv)
{
    const char *scene_path = NULL, *season = NULL, *years = NULL, *products = NULL;
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
        CLI_OPT_TEXT("--products", "LIST", products, "the files written, of raster (the GeoTIFFs and their QGIS "
                     "styles), maps (the pages: PNG, world file, PDF), summary (CSV, JSON) and layers (the "
                     "GeoPackage and its styles), separated by commas (default all; raster alone is what a GIS "
                     "viewshed writes)"),
        CLI_OPT_FLAG("--sightlines", o.sightlines, "every pair by its sightline, bare earth too, without the "
                     "bare-earth sweep (slower; the same maps)"),
        CLI_OPT_TEXT("--season", "S", season, CLI_HELP_SEASON),
        CLI_OPT_YEAR(bo),
        CLI_OPT_TEXT("--years", "LIST", years, "maps before the planting plan and at each of LIST's years since "
                     "planting (1,5,15,30) in DIR/before and DIR/year_N, what the planting hides each year "
                     "(ztv_hidden_by_planting.tif, .png, .pdf) and the area seeing the development against the years "
                     "(DIR/visible_area.csv, .png)"),
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

    cli_scene_use use = {.season = season, .no_camera = 1, .check_outputs = 1, /* the folder's files */
                         .build_for = build_for_map, .build_for_arg = &o};
    if (years && bo.planting_shown) {
        fprintf(stderr, "sylva ztv: give --year N or --years LIST, not both\n");
        return EXIT_USAGE;
    }
    if (years && (o.screening == ZTV_BARE || o.screening == ZTV_CANOPY)) {
        fprintf(stderr, "sylva ztv: --years maps what the planting hides, which bare earth and the canopy "
                "surface do not hold; give --screening vegetation or all\n");
        return EXIT_USAGE;
    }
    if (products && parse_products(products, &o.products)) return EXIT_USAGE;
    if (years && o.products && o.products != ZTV_PRODUCTS_ALL) {
        fprintf(stderr, "sylva ztv: --years reads each year's maps and summary back; give --products all or "
                "leave it out\n");
        return EXIT_USAGE;
    }
    if (years) return ztv_years_run(m, scene_path, &use, bo, &o, years);
    int rc = ztv_one(m, scene_path, &use, &bo, o, o.dir);
    if (!rc && !m->rank) printf("%s\n", o.dir);
    return rc;
}

int cmd_ztv(int argc, char **argv)
{
    cli_mpi m;
    int rc = cli_mpi_begin(&m, "ztv", argc, argv);
    if (!rc) rc = ztv_run(&m, argc, argv);
    return cli_mpi_end(&m, rc);
}
