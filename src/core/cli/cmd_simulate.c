/* cmd_simulate.c — `sylva simulate SCENE`: runs the scene's ecology alone, year by year, and
 * writes what was asked: the living plants as CSV, the whole run's state (to continue later
 * with --load), and statistics — plants per species per year as CSV and as a chart, and a
 * top-down map of the population at chosen years (scene_build/ecology_steps.h). */
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
#include "scene_build/ecology_steps.h"
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

int cmd_simulate(int argc, char **argv)
{
    const char *scene_path = NULL;
    year_list maps = {{0, 20, 60, 80, 180}, 5};
    ecology_steps_options o = {0};
    build_options bo = {.analysis = 1}; /* the ground as surveyed, whatever the camera */
    const cli_option options[] = {
        {.names = "--years", .type = CLI_WHOLE, .value = "N", .target = &o.years, .target_size = sizeof o.years,
         .max = 1000000, .given = &o.years_given, .help = "years to simulate (from the loaded state's year with "
         "--load); default: up to the scene's `years`"},
        CLI_OPT_PATH("-o, --output", "FILE", o.plants_csv, "the living plants as CSV: species,x,y,z,age,height,radius,vigour "
                     "(metres, years; vigour 0 to 1)"),
        CLI_OPT_PATH("--save", "STATE", o.save, "the whole run at the end (plants, year, random streams)"),
        CLI_OPT_PATH("--load", "STATE", o.load, "continue a run saved with --save from the same scene"),
        CLI_OPT_PATH("--stats", "DIR", o.stats_dir, "DIR/population.csv and DIR/population.png (plants per species per "
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
    o.map_years = maps.year, o.n_map_years = maps.n, o.quiet = bo.quiet, o.started = progress_now();

    cli_ecology e;
    err_buf err = {{0}};
    int rc = cli_ecology_open(&e, "simulate", scene_path, &bo);
    char stats_csv[4200] = "", stats_png[4200] = "";
    if (o.stats_dir) {
        snprintf(stats_csv, sizeof stats_csv, "%s/population.csv", o.stats_dir);
        snprintf(stats_png, sizeof stats_png, "%s/population.png", o.stats_dir);
    }
    cli_file inputs[] = {{o.load, "--load"}};
    cli_file outputs[] = {{o.plants_csv, "-o"}, {o.save, "--save"}, {o.stats_dir ? stats_csv : NULL, "--stats"},
                          {o.stats_dir ? stats_png : NULL, "--stats"}};
    if (!rc) rc = cli_outputs_check("simulate", e.base.sf, inputs, 1, outputs, 4);
    if (!rc && ecology_steps_run(e.session, e.base.sf, e.base.scene->surveyed, &o, &err))
        rc = cli_fail("simulate", &err, ERR_INTERNAL);
    cli_ecology_close(&e);
    return rc;
}
