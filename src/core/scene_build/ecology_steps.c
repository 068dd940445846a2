/* ecology_steps.c — an ecology run on its own, year by year, and its files (ecology_steps.h). */
#include "scene_build/ecology_steps.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/atomic_file.h"
#include "io/output_folder.h"
#include "io/population_plot.h"
#include "scene_build/ecology_maps.h"
#include "util/progress.h"

/* The plants per species counted every year of the run. */
typedef struct year_counts {
    uint32_t *counts;    /* owned: rows x n_species */
    uint32_t *years;     /* owned: the year of each row */
    const char **names;  /* owned array: the species' names (the scene file's strings) */
    uint32_t rows, n_species;
} year_counts;

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

static int write_population_csv(const char *path, const year_counts *c, err_buf *err)
{
    atomic_file out;
    FILE *f = atomic_file_open_stream(&out, path, err);
    if (!f) return -1;
    fprintf(f, "year");
    for (uint32_t s = 0; s < c->n_species; s++) fprintf(f, ",%s", c->names[s]);
    fputc('\n', f);
    for (uint32_t r = 0; r < c->rows; r++) {
        fprintf(f, "%u", c->years[r]);
        for (uint32_t s = 0; s < c->n_species; s++) fprintf(f, ",%u", c->counts[(size_t)r * c->n_species + s]);
        fputc('\n', f);
    }
    return atomic_file_commit(&out, err);
}

/* dir/map_YEAR.png of the session's plants now. */
static int write_map(ecology_session *e, const sylva_heightfield *ground, const char *dir, const year_counts *c,
                     err_buf *err)
{
    sylva_ecology_plant_record *p = NULL;
    uint32_t n = 0;
    if (ecology_session_plants(e, &p, &n, err)) return err_default(err, ERR_OUTPUT);
    char path[4200];
    uint32_t year = ecology_session_year(e);
    snprintf(path, sizeof path, "%s/map_%04u.png", dir, year);
    sylva_ecology_factor_map water = {0}, m;
    for (uint32_t i = 0; i < ecology_session_factor_count(e); i++)
        if (!ecology_session_factor(e, i, &m, err) && !strcmp(m.name, "water")) water = m;
    int rc = plant_map_write(path, ground, water.values ? &water : NULL, p, n, c->names, c->n_species, year, err);
    free(p);
    if (rc) return err_default(err, ERR_OUTPUT);
    printf("%s\n", path);
    return 0;
}

/* Steps n_years years, counting every year (the first and the last too) and mapping the chosen
 * ones. */
static int step_years(ecology_session *e, const sylva_heightfield *ground, const ecology_steps_options *o,
                      uint32_t n_years, year_counts *c, err_buf *err)
{
    progress prog;
    int rc = 0;
    progress_begin(&prog, "ecology", n_years, o->quiet);
    for (uint32_t y = 0;; y++) {
        uint32_t year = ecology_session_year(e);
        c->years[c->rows] = year;
        for (uint32_t s = 0; s < c->n_species; s++) c->counts[(size_t)c->rows * c->n_species + s] = ecology_session_count(e, s);
        c->rows++;
        int mapped = 0;
        for (uint32_t m = 0; o->stats_dir && m < o->n_map_years; m++) mapped |= o->map_years[m] == year;
        if (o->stats_dir && (mapped || y == n_years) && (rc = write_map(e, ground, o->stats_dir, c, err))) break;
        if (y == n_years) break;
        if ((rc = ecology_session_step(e, 1, err))) {
            err_default(err, ERR_PLUGIN);
            break;
        }
        progress_set(&prog, y + 1, n_years);
    }
    progress_end(&prog);
    return rc;
}

/* The files of the run's end: the plants, the state, the statistics. */
static int write_outputs(ecology_session *e, const scene_file *sf, const ecology_steps_options *o,
                         const year_counts *c, err_buf *err)
{
    if (o->plants_csv) {
        sylva_ecology_plant_record *p = NULL;
        uint32_t n = 0;
        if (ecology_session_plants(e, &p, &n, err)) return err_default(err, ERR_PLUGIN);
        int bad = write_plants_csv(o->plants_csv, sf, p, n, err);
        free(p);
        if (bad) return err_default(err, ERR_OUTPUT);
        printf("%s\n", o->plants_csv);
    }
    if (o->save) {
        if (ecology_session_save(e, o->save, err)) return err_default(err, ERR_OUTPUT);
        printf("%s\n", o->save);
    }
    if (o->stats_dir) {
        char path[4200];
        snprintf(path, sizeof path, "%s/population.csv", o->stats_dir);
        if (write_population_csv(path, c, err)) return err_default(err, ERR_OUTPUT);
        printf("%s\n", path);
        snprintf(path, sizeof path, "%s/population.png", o->stats_dir);
        if (population_plot_write(path, c->years, c->counts, c->rows, c->names, c->n_species, err))
            return err_default(err, ERR_OUTPUT);
        printf("%s\n", path);
    }
    return 0;
}

int ecology_steps_run(ecology_session *e, const scene_file *sf, const sylva_heightfield *ground,
                      const ecology_steps_options *o, err_buf *err)
{
    if (o->load && ecology_session_load(e, o->load, err)) return err_default(err, ERR_INPUT);
    uint32_t start = ecology_session_year(e), wanted = ecology_session_years_wanted(e);
    uint32_t n_years = o->years_given ? o->years : wanted > start ? wanted - start : 0;
    uint32_t ns = sf->n_species;
    year_counts c = {.counts = malloc(((size_t)n_years + 1) * (ns ? ns : 1) * sizeof *c.counts),
                     .years = malloc(((size_t)n_years + 1) * sizeof *c.years),
                     .names = calloc(ns ? ns : 1, sizeof *c.names), .n_species = ns};
    int rc = 0;
    if (!c.counts || !c.years || !c.names) rc = err_nomem(err, "out of memory for %u years of statistics", n_years);
    for (uint32_t s = 0; !rc && s < ns; s++) c.names[s] = sf->species[s].name;
    if (!rc && o->stats_dir && output_folder_make(o->stats_dir, err)) rc = err_default(err, ERR_OUTPUT);
    if (!rc) rc = step_years(e, ground, o, n_years, &c, err);
    if (!rc) rc = write_outputs(e, sf, o, &c, err);
    if (!rc && !o->quiet) {
        fprintf(stderr, "simulated years %u to %u in %.2fs:", start, ecology_session_year(e),
                progress_now() - o->started);
        for (uint32_t s = 0; s < ns; s++)
            fprintf(stderr, "%s %s %u", s ? "," : "", c.names[s], c.counts[(size_t)(c.rows - 1) * ns + s]);
        fprintf(stderr, "\n");
    }
    free(c.counts), free(c.years), free(c.names);
    return rc;
}
