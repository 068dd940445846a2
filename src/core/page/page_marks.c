/* page_marks.c — north arrow and scale bar (page_marks.h). */
#include "page/page_marks.h"

#include <math.h>
#include <stdio.h>

#include "page/page_text.h"

void page_north_arrow(cairo_t *cr, double x, double y, double size)
{
    double half = 0.3 * size, top = y - 0.75 * size;
    cairo_save(cr);
    cairo_move_to(cr, x, top);
    cairo_line_to(cr, x + half, y);
    cairo_line_to(cr, x, y - 0.25 * size);
    cairo_line_to(cr, x - half, y);
    cairo_close_path(cr);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 0.25);
    cairo_stroke(cr);
    cairo_move_to(cr, x, top);
    cairo_line_to(cr, x + half, y);
    cairo_line_to(cr, x, y - 0.25 * size);
    cairo_close_path(cr);
    cairo_fill(cr);
    page_font f = {.size_pt = size * 1.1, .bold = 1, .align = PAGE_CENTRE, .halo = 0.4};
    page_text(cr, x, top - size * 0.5, 0, &f, "N", 0);
    cairo_restore(cr);
}

void page_dot(cairo_t *cr, double x, double y, double r, const double rgb[3])
{
    cairo_save(cr);
    cairo_new_sub_path(cr);
    cairo_arc(cr, x, y, r, 0, 2 * M_PI);
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_set_line_width(cr, 0.15 * r + 0.1);
    cairo_stroke(cr);
    cairo_restore(cr);
}

double page_round_length(double most)
{
    if (!(most > 0)) return 0;
    double p = pow(10.0, floor(log10(most)));
    return most >= 5 * p ? 5 * p : most >= 2 * p ? 2 * p : p;
}

void page_length_text(double metres, char *out, size_t n)
{
    if (metres >= 1000) snprintf(out, n, "%g km", metres / 1000);
    else snprintf(out, n, "%g m", metres);
}

double page_scale_bar(cairo_t *cr, double x, double y, double max_mm, double mm_per_m)
{
    double metres = page_round_length(max_mm / mm_per_m), len = metres * mm_per_m;
    cairo_save(cr);
    cairo_set_line_width(cr, 0.25);
    for (int k = 0; k < 4; k++) { /* four blocks, black and white by turns */
        cairo_rectangle(cr, x + k * len / 4, y, len / 4, 1.2);
        cairo_set_source_rgb(cr, k % 2 ? 1 : 0, k % 2 ? 1 : 0, k % 2 ? 1 : 0);
        cairo_fill_preserve(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_stroke(cr);
    }
    char text[32];
    page_font f = {.size_pt = 6.5, .align = PAGE_CENTRE, .halo = 0.4};
    page_text(cr, x, y + 1.6, 0, &f, "0", 0);
    page_length_text(metres, text, sizeof text);
    page_text(cr, x + len, y + 1.6, 0, &f, text, 0);
    cairo_restore(cr);
    return len;
}
