/* ztv_years_chart.c — the visible and hidden areas against the years since planting, drawn with
 * cairo and pango (ztv_years_chart.h). */
#include "ztv/ztv_years_chart.h"

#include <math.h>
#include <stdio.h>

#include "page/page.h"
#include "page/page_marks.h"
#include "page/page_text.h"

#define CHART_WIDTH 190.0  /* millimetres */
#define CHART_HEIGHT 105.0
#define CHART_DPI 200.0
#define PANEL_TOP 22.0     /* the plotting area's top, below the titles */
#define PANEL_BOTTOM 78.0  /* its bottom: the x axis */
#define KEY_TOP 90.0       /* the legends' and notes' first line, under the axis's label */

static const double ink[3] = {0.1, 0.1, 0.1}, grid_grey[3] = {0.85, 0.85, 0.85};
static const double with_plan[3] = {0.1, 0.32, 0.75}, before_plan[3] = {0.45, 0.45, 0.45};
static const double hidden_all[3] = {0.1, 0.31, 0.78}, hidden_part[3] = {0.43, 0.75, 0.94};

/* A plotting area: x from 0 to xmax (years), y from 0 to ymax, placed in millimetres. */
typedef struct panel {
    double left, right, top, bottom;
    double xmax, ymax;
} panel;

static double px(const panel *p, double x) { return p->left + (p->right - p->left) * x / p->xmax; }
static double py(const panel *p, double y) { return p->bottom - (p->bottom - p->top) * y / p->ymax; }

/* The axis's top: the least round step times a whole number over `most` (about five steps). */
static double axis_top(double most, double *step)
{
    if (!(most > 0)) most = 1;
    *step = page_round_length(most / 4);
    if (*step * 6 < most) *step = page_round_length(most / 2);
    return ceil(most / *step - 1e-9) * *step;
}

static void set_rgb(cairo_t *cr, const double c[3]) { cairo_set_source_rgb(cr, c[0], c[1], c[2]); }

/* The decimals that write every multiple of step exactly (up to 6). */
static int step_digits(double step)
{
    int d = 0;
    for (double k = step; d < 6 && fabs(k - round(k)) > 1e-6 * k; k *= 10) d++;
    return d;
}

/* Gridlines, ticks and their numbers on both axes, the axes' labels. */
static void draw_axes(cairo_t *cr, const panel *p, double xstep, double ystep, const char *ylabel)
{
    int ydigits = step_digits(ystep);
    page_font num = {.size_pt = 7, .align = PAGE_RIGHT, .rgb = {0.2, 0.2, 0.2}}, lab = {.size_pt = 7.5};
    char text[64];
    cairo_set_line_width(cr, 0.15);
    for (double y = 0; y <= p->ymax * 1.0001; y += ystep) {
        set_rgb(cr, grid_grey);
        cairo_move_to(cr, p->left, py(p, y)), cairo_line_to(cr, p->right, py(p, y)), cairo_stroke(cr);
        snprintf(text, sizeof text, "%.*f", ydigits, y);
        page_text(cr, p->left - 1.5, py(p, y) - 1.6, 0, &num, text, 0);
    }
    num.align = PAGE_CENTRE;
    for (double x = 0; x <= p->xmax * 1.0001; x += xstep) {
        snprintf(text, sizeof text, "%g", x);
        page_text(cr, px(p, x), p->bottom + 1.2, 0, &num, text, 0);
    }
    set_rgb(cr, ink);
    cairo_set_line_width(cr, 0.3);
    cairo_move_to(cr, p->left, p->top), cairo_line_to(cr, p->left, p->bottom), cairo_line_to(cr, p->right, p->bottom);
    cairo_stroke(cr);
    lab.align = PAGE_CENTRE;
    page_text(cr, 0.5 * (p->left + p->right), p->bottom + 5.5, 0, &lab, "years since planting", 0);
    lab.align = PAGE_LEFT;
    page_text(cr, p->left - 12, p->top - 6, 0, &lab, ylabel, 0);
}

/* A series through the years' points (n of them), with a dot at each unless dashed. */
static void draw_series(cairo_t *cr, const panel *p, const double *x, uint32_t n, const double *y, const double c[3],
                        int dashed)
{
    set_rgb(cr, c);
    cairo_set_line_width(cr, 0.5);
    if (dashed) cairo_set_dash(cr, (const double[]){1.5, 1.0}, 2, 0);
    for (uint32_t r = 0; r < n; r++)
        (r == 0 ? cairo_move_to : cairo_line_to)(cr, px(p, x[r]), py(p, y[r]));
    cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0);
    for (uint32_t r = 0; r < n && !dashed; r++) {
        cairo_arc(cr, px(p, x[r]), py(p, y[r]), 0.7, 0, 2 * M_PI);
        cairo_fill(cr);
    }
}

/* A legend line: a swatch of colour c and its text at (x, y). */
static void legend(cairo_t *cr, double x, double y, const double c[3], int dashed, const char *text)
{
    set_rgb(cr, c);
    cairo_set_line_width(cr, 0.6);
    if (dashed) cairo_set_dash(cr, (const double[]){1.5, 1.0}, 2, 0);
    cairo_move_to(cr, x, y + 1.6), cairo_line_to(cr, x + 6, y + 1.6), cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0);
    page_font f = {.size_pt = 7};
    page_text(cr, x + 7.5, y, 0, &f, text, 0);
}

/* The left panel: the area seeing the development, before the plan and each year, from zero. */
static void draw_visible(cairo_t *cr, const ztv_years_areas *a, double xmax, double xstep)
{
    double before[256], most = a->before_km2;
    for (uint32_t r = 0; r < a->n; r++) before[r] = a->before_km2, most = fmax(most, a->visible_km2[r]);
    double step, top = axis_top(most, &step);
    panel p = {.left = 20, .right = 92, .top = PANEL_TOP, .bottom = PANEL_BOTTOM, .xmax = xmax, .ymax = top};
    draw_axes(cr, &p, xstep, step, "area seeing the development (km\u00b2)");
    draw_series(cr, &p, a->year, a->n, before, before_plan, 1);
    draw_series(cr, &p, a->year, a->n, a->visible_km2, with_plan, 0);
    char text[160];
    double fall = a->before_km2 - a->visible_km2[a->n - 1];
    snprintf(text, sizeof text, "year %g: %.4g km\u00b2 less than before the planting (%.2g %%)", a->year[a->n - 1],
             fall, a->before_km2 > 0 ? 100 * fall / a->before_km2 : 0);
    page_font note = {.size_pt = 6.5, .rgb = {0.25, 0.25, 0.25}};
    legend(cr, p.left - 12, KEY_TOP, before_plan, 1, "before the planting");
    legend(cr, p.left + 30, KEY_TOP, with_plan, 0, "with the planting");
    page_text(cr, p.left - 12, KEY_TOP + 4.5, 0, &note, text, 0);
}

/* The right panel: the area where the planting hides all or part of what was seen, hectares. */
static void draw_hidden(cairo_t *cr, const ztv_years_areas *a, double xmax, double xstep)
{
    double all[256], part[256], most = 0;
    for (uint32_t r = 0; r < a->n; r++) {
        all[r] = 100 * a->hidden_km2[r], part[r] = 100 * a->partly_km2[r];
        most = fmax(most, fmax(all[r], part[r]));
    }
    double step, top = axis_top(most, &step);
    panel p = {.left = 118, .right = 184, .top = PANEL_TOP, .bottom = PANEL_BOTTOM, .xmax = xmax, .ymax = top};
    draw_axes(cr, &p, xstep, step, "area where the planting hides it (ha)");
    draw_series(cr, &p, a->year, a->n, part, hidden_part, 0);
    draw_series(cr, &p, a->year, a->n, all, hidden_all, 0);
    legend(cr, p.left - 12, KEY_TOP, hidden_all, 0, "every target seen before hidden");
    legend(cr, p.left - 12, KEY_TOP + 4.5, hidden_part, 0, "some of them hidden");
}

static int draw_chart(cairo_t *cr, const page_size *size, void *ctx, err_buf *err)
{
    (void)size, (void)err;
    const ztv_years_areas *a = ctx;
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    page_font title = {.size_pt = 10, .bold = 1};
    page_text(cr, 8, 4, 0, &title, "Where the development is seen from, over the years since planting", 0);
    double xstep, xmax = axis_top(a->year[a->n - 1], &xstep);
    draw_visible(cr, a, xmax, xstep);
    draw_hidden(cr, a, xmax, xstep);
    return 0;
}

int ztv_years_chart_write(const char *png_path, const ztv_years_areas *a, err_buf *err)
{
    if (a->n < 1 || a->n > 255)
        return err_set(err, "%s: a chart of %u years; it takes 1 to 255", png_path, a->n);
    page_size size = {CHART_WIDTH, CHART_HEIGHT, CHART_DPI};
    return page_write(&size, draw_chart, (void *)a, NULL, png_path, err);
}
