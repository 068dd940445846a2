/* population_plot.h — line charts: the chart of plants per species over the simulated years (as in Zamuda
 * 2006, Fig. C.13): one coloured line per species, axes with round-numbered ticks, a legend
 * with the species' names, written as a PNG. */
#ifndef SYLVA_POPULATION_PLOT_H
#define SYLVA_POPULATION_PLOT_H

#include <stdint.h>

#include "util/err.h"

/* counts holds n_rows rows of n_species counts; row r is the year years[r] (increasing).
 * Species i is drawn in canvas_series_color(i). Returns 0, or -1 with err set. */
int population_plot_write(const char *path, const uint32_t *years, const uint32_t *counts, uint32_t n_rows,
                          const char *const *names, uint32_t n_species, err_buf *err);

/* A chart of n_series lines over n_rows points: x[r] (increasing) against values[r * n_series + s],
 * the y axis from 0 (y_fit: over the values' range, rounded), series s drawn in
 * canvas_series_color(s) and named names[s] in the legend; markers: a dot at every point. */
typedef struct line_chart {
    const char *title, *x_label;
    const double *x, *values;
    uint32_t n_rows;
    const char *const *names;
    uint32_t n_series;
    int markers;
    int y_fit;
} line_chart;

/* Writes ch as a PNG at path. Returns 0, or -1 with err set. */
int line_chart_write(const char *path, const line_chart *ch, err_buf *err);

/* A round step (1, 2 or 5 times a power of ten) that cuts [0, span] into about `ticks` parts. */
double population_plot_tick_step(double span, int ticks);

#endif
