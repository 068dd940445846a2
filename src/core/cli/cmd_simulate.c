/* cmd_simulate.c — `sylva simulate SCENE`: runs the scene's ecology alone, year by year, and
 * writes what was asked: the living plants as CSV, the whole run's state (to continue later
 * with --load), and statistics — plants per species per year as CSV and as a chart, and a
 * top-down map of the population at chosen years. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli_args.h"
#include "cli/cli_ecology.h"
#include "cli/cli_options.h"
#include "cli/cli_outputs.h"
#include "cli/cli_status.h"
#include "cli/commands.h"
#include "io/atomic_file.h"
#include "scene/ecology_maps.h"
#include "io/population_plot.h"
#include "util/progress.h"

#define MAX_MAP_YEARS 64

static const char simulate_about[] =
    "Runs the scene's ecology (the plants it grows on the terrain) year by year without\n"
    "rendering.\n";

static const char simulate_epilogue[] =
    "A run continued from a state gives the same plants as one run without stopping.\n\n"
    "exit status: 0 done, 1 usage, 2 bad scene or plugin failure, 3 output not written,\n"
    "4 out of memory or internal error\n";

/* The years --maps names. */
typedef struct year_list {
    uint32_t year[MAX_MAP_YEARS];
    uint32_t n;
} year_list;

/* --maps Y,Y,...: a CLI_CUSTOM option's parser into a year_list. */
static int parse_years_list(const char *cmd, const char *opt, const char *s, void *target)
{
    year_list *m = target;
    uint32_t *years = m->year, *n = &m->n;
    *n = 0;
    const char *c = s;
    while (*c) {
        char *end;
        errno = 0;
        unsigned long v = *c >= '0' && *c <= '9' ? strtoul(c, &end, 10) : 0;
        if (!(*c >= '0' && *c <= '9') || errno || v > 1000000 || (*end && *end != ',') || *n == MAX_MAP_YEARS) {
            fprintf(stderr, "sylva %s: %s expects up to %d years separated by commas (e.g. 0,20,60), got '%s'\n",
                    cmd, opt, MAX_MAP_YEARS, s);
            return -1;
        }
        years[(*n)++] = (uint32_t)v;
        c = *end ? end + 1 : end;
    }
    return 0;
}

static int write_plants_csv(const char *path, const scene_file *sf, const sylva_ecology_plant_record *p, uint32_t n,
                            err_buf *err)
{
    atomic_file out;
    FILE *f = atomic_file_open_stream(&out, path, err);
    if (!f) return -1;
    fprintf(f, "species,x,y,z,age,height,radius,vigour\n");
    for (uint32_t i = 0; i < n; i++)
        fprintf(f, "%s,%.3f,%.3f,%.3f,%.0f,%.3f,%.3f,%.4f\n", sf->species[p[i].species].name, p[i].position[0],
                p[i].position[1], p[i].position[2], p[i].age, p[i].height, p[i].radius, p[i].vigour);
    return atomic_file_commit(&out, err);
}

static int write_population_csv(const char *path, const scene_file *sf, const uint32_t *years,
                                const uint32_t *counts, uint32_t rows, err_buf *err)
{
    atomic_file out;
    FILE *f = atomic_file_open_stream(&out, path, err);
    if (!f) return -1;
    fprintf(f, "year");
    for (uint32_t s = 0; s < sf->n_species; s++) fprintf(f, ",%s", sf->species[s].name);
    fputc('\n', f);
    for (uint32_t r = 0; r < rows; r++) {
        fprintf(f, "%u", years[r]);
        for (uint32_t s = 0; s < sf->n_species; s++) fprintf(f, ",%u", counts[(size_t)r * sf->n_species + s]);
        fputc('\n', f);
    }
    return atomic_file_commit(&out, err);
}

static int write_map(cli_ecology *e, const char *dir, const char *const *names, err_buf *err)
{
    sylva_ecology_plant_record *p = NULL;
    uint32_t n = 0;
    if (ecology_session_plants(e->session, &p, &n, err)) return -1;
    char path[4200];
    uint32_t year = ecology_session_year(e->session);
    snprintf(path, sizeof path, "%s/map_%04u.png", dir, year);
    sylva_ecology_factor_map water = {0}, m;
    for (uint32_t i = 0; i < ecology_session_factor_count(e->session); i++)
        if (!ecology_session_factor(e->session, i, &m, err) && !strcmp(m.name, "water")) water = m;
    int rc = plant_map_write(path, e->base.scene->surveyed, water.values ? &water : NULL, p, n, names, e->base.sf->n_species,
                             year, err);
    free(p);
    if (rc) return err_default(err, ERR_OUTPUT);
    printf("%s\n", path);
    return 0;
}

int cmd_simulate(int argc, char **argv)
{
    const char *scene_path = NULL, *out = NULL, *save = NULL, *load = NULL, *stats = NULL;
    year_list maps = {{0, 20, 60, 80, 180}, 5};
    uint64_t years = 0;
    int years_given = 0;
    build_options bo = {.analysis = 1}; /* the ground as surveyed, whatever the camera */
    const cli_option options[] = {
        {.names = "--years", .type = CLI_WHOLE, .value = "N", .target = &years, .target_size = sizeof years,
         .max = 1000000, .given = &years_given, .help = "years to simulate (from the loaded state's year with "
         "--load); default: up to the scene's `years`"},
        CLI_OPT_PATH("-o, --output", "FILE", out, "the living plants as CSV: species,x,y,z,age,height,radius,vigour "
                     "(metres, years; vigour 0 to 1)"),
        CLI_OPT_PATH("--save", "STATE", save, "the whole run at the end (plants, year, random streams)"),
        CLI_OPT_PATH("--load", "STATE", load, "continue a run saved with --save from the same scene"),
        CLI_OPT_PATH("--stats", "DIR", stats, "DIR/population.csv and DIR/population.png (plants per species per "
                     "year) and DIR/map_YEAR.png (the plants seen from above)"),
        {.names = "--maps", .type = CLI_CUSTOM, .value = "Y,Y,...", .target = &maps, .parse = parse_years_list,
         .help = "the years to map with --stats (default 0,20,60,80,180 and the last year)"},
        CLI_OPT_WHOLE("--threads", "N", bo.threads, 1, 1024, "threads for the tree models and the ecology's "
                      "workers (default: one per core); the plants do not depend on it"),
        CLI_OPTS_SCENE_COMMON(bo),
    };
    const cli_command_spec spec = {"simulate", "SCENE", simulate_about, NULL, options,
                                   sizeof options / sizeof *options, simulate_epilogue, cli_operand_scene,
                                   &scene_path};
    int parsed = cli_options_parse(&spec, argc, argv);
    if (parsed) return cli_options_status(parsed);
    const uint32_t *map_years = maps.year, n_map_years = maps.n;

    double t0 = progress_now();
    cli_ecology e;
    int rc = cli_ecology_open(&e, "simulate", scene_path, &bo);
    err_buf err = {{0}};
    uint32_t *counts = NULL, *row_years = NULL, rows = 0;
    const char **names = NULL;
    if (rc) goto done;
    char stats_csv[4200] = "", stats_png[4200] = "";
    if (stats) {
        snprintf(stats_csv, sizeof stats_csv, "%s/population.csv", stats);
        snprintf(stats_png, sizeof stats_png, "%s/population.png", stats);
    }
    cli_file inputs[] = {{load, "--load"}};
    cli_file outputs[] = {{out, "-o"}, {save, "--save"}, {stats ? stats_csv : NULL, "--stats"},
                          {stats ? stats_png : NULL, "--stats"}};
    if ((rc = cli_outputs_check("simulate", e.base.sf, inputs, 1, outputs, 4))) goto done;
    if (load && ecology_session_load(e.session, load, &err)) {
        rc = cli_fail("simulate", &err, ERR_INPUT);
        goto done;
    }
    uint32_t start = ecology_session_year(e.session), wanted = ecology_session_years_wanted(e.session);
    uint32_t n_years = years_given ? (uint32_t)years : wanted > start ? wanted - start : 0;
    uint32_t ns = e.base.sf->n_species;
    counts = malloc(((size_t)n_years + 1) * (ns ? ns : 1) * sizeof *counts);
    row_years = malloc(((size_t)n_years + 1) * sizeof *row_years);
    names = calloc(ns ? ns : 1, sizeof *names);
    if (!counts || !row_years || !names) {
        rc = cli_failf("simulate", ERR_NOMEM, "out of memory for %u years of statistics", n_years);
        goto done;
    }
    for (uint32_t s = 0; s < ns; s++) names[s] = e.base.sf->species[s].name;
    if (stats && cli_make_folder(stats, &err)) {
        rc = cli_fail("simulate", &err, ERR_OUTPUT);
        goto done;
    }
    progress prog;
    progress_begin(&prog, "ecology", n_years, bo.quiet);
    for (uint32_t y = 0;; y++) {
        uint32_t year = ecology_session_year(e.session);
        row_years[rows] = year;
        for (uint32_t s = 0; s < ns; s++) counts[(size_t)rows * ns + s] = ecology_session_count(e.session, s);
        rows++;
        int mapped = 0;
        for (uint32_t m = 0; stats && m < n_map_years; m++) mapped |= map_years[m] == year;
        if (stats && (mapped || y == n_years) && write_map(&e, stats, names, &err)) {
            progress_end(&prog);
            rc = cli_fail("simulate", &err, ERR_OUTPUT);
            goto done;
        }
        if (y == n_years) break;
        if (ecology_session_step(e.session, 1, &err)) {
            progress_end(&prog);
            rc = cli_fail("simulate", &err, ERR_PLUGIN);
            goto done;
        }
        progress_set(&prog, y + 1, n_years);
    }
    progress_end(&prog);
    if (out) {
        sylva_ecology_plant_record *p = NULL;
        uint32_t n = 0;
        if (ecology_session_plants(e.session, &p, &n, &err)) {
            rc = cli_fail("simulate", &err, ERR_PLUGIN);
            goto done;
        }
        int bad = write_plants_csv(out, e.base.sf, p, n, &err);
        free(p);
        if (bad) {
            rc = cli_fail("simulate", &err, ERR_OUTPUT);
            goto done;
        }
        printf("%s\n", out);
    }
    if (save) {
        if (ecology_session_save(e.session, save, &err)) {
            rc = cli_fail("simulate", &err, ERR_OUTPUT);
            goto done;
        }
        printf("%s\n", save);
    }
    if (stats) {
        char path[4200];
        snprintf(path, sizeof path, "%s/population.csv", stats);
        if (write_population_csv(path, e.base.sf, row_years, counts, rows, &err)) {
            rc = cli_fail("simulate", &err, ERR_OUTPUT);
            goto done;
        }
        printf("%s\n", path);
        snprintf(path, sizeof path, "%s/population.png", stats);
        if (population_plot_write(path, row_years, counts, rows, names, ns, &err)) {
            rc = cli_fail("simulate", &err, ERR_OUTPUT);
            goto done;
        }
        printf("%s\n", path);
    }
    if (!bo.quiet) {
        fprintf(stderr, "simulated years %u to %u in %.2fs:", start, ecology_session_year(e.session),
                progress_now() - t0);
        for (uint32_t s = 0; s < ns; s++)
            fprintf(stderr, "%s %s %u", s ? "," : "", names[s], counts[(size_t)(rows - 1) * ns + s]);
        fprintf(stderr, "\n");
    }
done:
    free(counts), free(row_years), free(names);
    cli_ecology_close(&e);
    return rc;
}
