/* ecology_steps.h — an ecology run on its own (`sylva simulate`): the session continued from a
 * saved state when asked, stepped year by year with the plants per species counted every year
 * and mapped from above in chosen years, then the living plants as CSV, the state saved, and
 * the statistics as CSV and a chart. Each file written is printed on stdout as it is. */
#ifndef SYLVA_ECOLOGY_STEPS_H
#define SYLVA_ECOLOGY_STEPS_H

#include <stdint.h>

#include "scene_build/ecology_session.h"
#include "sylva/plugin.h"
#include "scene_file/scene_file.h"
#include "util/err.h"

typedef struct ecology_steps_options {
    uint32_t years;            /* years to step */
    int years_given;           /* 0: up to the scene's `years` from the session's year */
    const char *load;          /* NULL, or a state to continue from */
    const char *plants_csv;    /* NULL, or the living plants at the end */
    const char *save;          /* NULL, or where the state at the end goes */
    const char *stats_dir;     /* NULL, or the folder of population.csv/.png and map_YEAR.png */
    const uint32_t *map_years; /* the years mapped with stats_dir (and the last year) */
    uint32_t n_map_years;
    int quiet;                 /* no progress or closing line */
    double started;            /* progress_now() when the command began, for the closing line */
} ecology_steps_options;

/* Runs the steps on session e of sf's scene, whose DTM as surveyed is `ground` (under the
 * maps). Returns 0, or -1 with err set and its kind stated. */
int ecology_steps_run(ecology_session *e, const scene_file *sf, const sylva_heightfield *ground,
                      const ecology_steps_options *o, err_buf *err);

#endif
