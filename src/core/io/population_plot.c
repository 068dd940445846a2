/* population_plot.c — plants per species per year as a line chart on a raster canvas. */
#include "io/population_plot.h"

#include <math.h>
#include <stdio.h>

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

int population_plot_write(const char *path, const uint32_t *years, const uint32_t *counts, uint32_t n_rows,
                          const char *const *names, uint32_t n_species, err_buf *err)
{
    static const uint8_t white[3] = {255, 255, 255}, ink[3] = {30, 30, 30}, grid[3] = {225, 225, 225};
    const int w = 900, h = 500, left = 70, right = 170, top = 40, bottom = 50;
    canvas c;
    if (canvas_init(&c, w, h, white, err)) return -1;
    uint32_t y_first = n_rows ? years[0] : 0, y_last = n_rows ? years[n_rows - 1] : 1;
    if (y_last <= y_first) y_last = y_first + 1;
    uint32_t max_count = 1;
    for (size_t i = 0; i < (size_t)n_rows * n_species; i++) max_count = counts[i] > max_count ? counts[i] : max_count;
    double x_step = population_plot_tick_step(y_last - y_first, 8);
    double c_step = population_plot_tick_step(max_count, 6);
    double c_top = ceil(max_count / c_step) * c_step;
    int px0 = left, px1 = w - right, py0 = h - bottom, py1 = top;
#define X_OF(year) (px0 + ((double)(year) - y_first) / (y_last - y_first) * (px1 - px0))
#define Y_OF(n) (py0 - (double)(n) / c_top * (py0 - py1))
    char label[64];
    for (double v = 0; v <= c_top + 0.5 * c_step; v += c_step) {
        int y = (int)lround(Y_OF(v));
        canvas_rect(&c, px0, y, px1, y, grid);
        snprintf(label, sizeof label, "%.0f", v);
        canvas_text(&c, px0 - 8 - canvas_text_width(label, 1), y - 3, label, 1, ink);
    }
    for (double v = ceil(y_first / x_step) * x_step; v <= y_last + 1e-9; v += x_step) {
        int x = (int)lround(X_OF(v));
        canvas_rect(&c, x, py1, x, py0, grid);
        canvas_rect(&c, x, py0, x, py0 + 4, ink);
        snprintf(label, sizeof label, "%.0f", v);
        canvas_text(&c, x - canvas_text_width(label, 1) / 2, py0 + 9, label, 1, ink);
    }
    canvas_rect(&c, px0, py1, px0, py0, ink);
    canvas_rect(&c, px0, py0, px1, py0, ink);
    canvas_text(&c, px0, 12, "plants per species", 2, ink);
    canvas_text(&c, (px0 + px1) / 2 - canvas_text_width("year", 1) / 2, h - 18, "year", 1, ink);
    for (uint32_t s = 0; s < n_species; s++) {
        uint8_t col[3];
        canvas_series_color(s, col);
        for (uint32_t r = 1; r < n_rows; r++)
            canvas_line(&c, X_OF(years[r - 1]), Y_OF(counts[(size_t)(r - 1) * n_species + s]), X_OF(years[r]),
                        Y_OF(counts[(size_t)r * n_species + s]), 2.0, col);
        if (n_rows == 1) canvas_disc(&c, X_OF(years[0]), Y_OF(counts[s]), 2.5, col);
        int ly = top + 10 + 20 * (int)s;
        canvas_rect(&c, px1 + 20, ly, px1 + 32, ly + 8, col);
        canvas_text(&c, px1 + 40, ly + 1, names[s] ? names[s] : "?", 1, ink);
    }
#undef X_OF
#undef Y_OF
    int rc = canvas_write_png(&c, path, err);
    canvas_free(&c);
    return rc;
}
