/* population_plot.c — line charts on a raster canvas: plants per species per year, and any
 * series against years (population_plot.h). */
#include "io/population_plot.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "io/raster_canvas.h"

double population_plot_tick_step(double span, int ticks)
{
    if (!(span > 0)) return 1;
    double raw = span / (ticks > 0 ? ticks : 1);
    double p = pow(10, floor(log10(raw)));
    double m = raw / p;
    double step = m <= 1 ? 1 : m <= 2 ? 2 : m <= 5 ? 5 : 10;
    return step * p;
}

int line_chart_write(const char *path, const line_chart *ch, err_buf *err)
{
    static const uint8_t white[3] = {255, 255, 255}, ink[3] = {30, 30, 30}, grid[3] = {225, 225, 225};
    const int w = 900, h = 500, left = 70, right = 170, top = 40, bottom = 50;
    const uint32_t n_rows = ch->n_rows, n_series = ch->n_series;
    canvas c;
    if (canvas_init(&c, w, h, white, err)) return -1;
    double x_first = n_rows ? ch->x[0] : 0, x_last = n_rows ? ch->x[n_rows - 1] : 1;
    if (x_last <= x_first) x_last = x_first + 1;
    double max_value = 0, min_value = INFINITY;
    for (size_t i = 0; i < (size_t)n_rows * n_series; i++)
        max_value = fmax(max_value, ch->values[i]), min_value = fmin(min_value, ch->values[i]);
    if (!(max_value > 0)) max_value = 1;
    double x_step = population_plot_tick_step(x_last - x_first, 8);
    double c_step = population_plot_tick_step(ch->y_fit && max_value > min_value ? max_value - min_value : max_value, 6);
    double c_top = ceil(max_value / c_step) * c_step;
    double c_bottom = ch->y_fit && max_value > min_value ? floor(min_value / c_step) * c_step : 0;
    if (!(c_top > c_bottom)) c_top = c_bottom + c_step;
    int px0 = left, px1 = w - right, py0 = h - bottom, py1 = top;
#define X_OF(v) (px0 + ((double)(v) - x_first) / (x_last - x_first) * (px1 - px0))
#define Y_OF(n) (py0 - ((double)(n) - c_bottom) / (c_top - c_bottom) * (py0 - py1))
    char label[64];
    for (double v = c_bottom; v <= c_top + 0.5 * c_step; v += c_step) {
        int y = (int)lround(Y_OF(v));
        canvas_rect(&c, px0, y, px1, y, grid);
        snprintf(label, sizeof label, "%.6g", v);
        canvas_text(&c, px0 - 8 - canvas_text_width(label, 1), y - 3, label, 1, ink);
    }
    for (double v = ceil(x_first / x_step) * x_step; v <= x_last + 1e-9; v += x_step) {
        int x = (int)lround(X_OF(v));
        canvas_rect(&c, x, py1, x, py0, grid);
        canvas_rect(&c, x, py0, x, py0 + 4, ink);
        snprintf(label, sizeof label, "%.6g", v);
        canvas_text(&c, x - canvas_text_width(label, 1) / 2, py0 + 9, label, 1, ink);
    }
    canvas_rect(&c, px0, py1, px0, py0, ink);
    canvas_rect(&c, px0, py0, px1, py0, ink);
    canvas_text(&c, px0, 12, ch->title, 2, ink);
    canvas_text(&c, (px0 + px1) / 2 - canvas_text_width(ch->x_label, 1) / 2, h - 18, ch->x_label, 1, ink);
    for (uint32_t s = 0; s < n_series; s++) {
        uint8_t col[3];
        canvas_series_color(s, col);
        for (uint32_t r = 1; r < n_rows; r++)
            canvas_line(&c, X_OF(ch->x[r - 1]), Y_OF(ch->values[(size_t)(r - 1) * n_series + s]), X_OF(ch->x[r]),
                        Y_OF(ch->values[(size_t)r * n_series + s]), 2.0, col);
        for (uint32_t r = 0; r < n_rows && ch->markers; r++)
            canvas_disc(&c, X_OF(ch->x[r]), Y_OF(ch->values[(size_t)r * n_series + s]), 3.5, col);
        if (n_rows == 1 && !ch->markers) canvas_disc(&c, X_OF(ch->x[0]), Y_OF(ch->values[s]), 2.5, col);
        int ly = top + 10 + 20 * (int)s;
        canvas_rect(&c, px1 + 20, ly, px1 + 32, ly + 8, col);
        canvas_text(&c, px1 + 40, ly + 1, ch->names[s] ? ch->names[s] : "?", 1, ink);
    }
#undef X_OF
#undef Y_OF
    int rc = canvas_write_png(&c, path, err);
    canvas_free(&c);
    return rc;
}

int population_plot_write(const char *path, const uint32_t *years, const uint32_t *counts, uint32_t n_rows,
                          const char *const *names, uint32_t n_species, err_buf *err)
{
    double *x = malloc(((size_t)n_rows + 1) * sizeof *x); /* owned here */
    double *values = malloc(((size_t)n_rows * n_species + 1) * sizeof *values); /* owned here */
    if (!x || !values) {
        free(x), free(values);
        return err_nomem(err, "out of memory drawing %s", path);
    }
    for (uint32_t r = 0; r < n_rows; r++) x[r] = years[r];
    for (size_t i = 0; i < (size_t)n_rows * n_species; i++) values[i] = counts[i];
    line_chart ch = {.title = "plants per species", .x_label = "year", .x = x, .values = values, .n_rows = n_rows,
                     .names = names, .n_series = n_species};
    int rc = line_chart_write(path, &ch, err);
    free(x), free(values);
    return rc;
}
