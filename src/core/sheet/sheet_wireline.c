/* sheet_wireline.c — the wireline's polylines stroked over a sheet's picture (sheet_wireline.h). */
#include "sheet/sheet_wireline.h"

/* One polyline as a path in the picture's pixels scaled to the rectangle. */
static void add_polyline(cairo_t *cr, const wireline_paths *p, const wireline_polyline *l)
{
    const double(*pts)[2] = (const double(*)[2])(p->points + l->first);
    if (l->n == 1) { /* a pixel alone: a dot, the round cap of a line of no length */
        cairo_move_to(cr, pts[0][0], pts[0][1]);
        cairo_line_to(cr, pts[0][0], pts[0][1]);
        return;
    }
    uint32_t segments = l->closed ? l->n : l->n - 1;
    int on_frame = 0;
    for (uint32_t k = 0; l->kind == WIRELINE_OUTLINE && k < segments && !on_frame; k++)
        on_frame = wireline_on_frame(p, pts[k], pts[(k + 1) % l->n]);
    if (l->closed && !on_frame) { /* a closed path, joined all round */
        cairo_move_to(cr, pts[0][0], pts[0][1]);
        for (uint32_t k = 1; k < l->n; k++) cairo_line_to(cr, pts[k][0], pts[k][1]);
        cairo_close_path(cr);
        return;
    }
    int drawing = 0;
    for (uint32_t k = 0; k < segments; k++) {
        const double *a = pts[k], *b = pts[(k + 1) % l->n];
        if (l->kind == WIRELINE_OUTLINE && wireline_on_frame(p, a, b)) {
            drawing = 0;
            continue;
        }
        if (!drawing) cairo_move_to(cr, a[0], a[1]);
        cairo_line_to(cr, b[0], b[1]);
        drawing = 1;
    }
}

/* Every polyline of kind as one path, stroked width millimetres wide in rgb. */
static void stroke_kind(cairo_t *cr, const wireline_paths *p, wireline_kind kind, double width, const double rgb[3],
                        double px_per_mm)
{
    cairo_new_path(cr);
    for (uint32_t k = 0; k < p->n_lines; k++)
        if (p->lines[k].kind == kind) add_polyline(cr, p, &p->lines[k]);
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
    cairo_set_line_width(cr, width * px_per_mm);
    cairo_stroke(cr);
}

void sheet_wireline_draw(cairo_t *cr, const wireline_paths *p, double x, double y, double w, double h)
{
    if (!p || !p->width || !p->height) return;
    cairo_save(cr);
    cairo_rectangle(cr, x, y, w, h);
    cairo_clip(cr);
    cairo_translate(cr, x, y);
    double sx = w / p->width, sy = h / p->height;
    cairo_scale(cr, sx, sy); /* the picture's pixels; square on the page */
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    stroke_kind(cr, p, WIRELINE_EDGE, SHEET_EDGE_MM, (const double[3]){1, 0.86, 0}, 1 / sx);
    stroke_kind(cr, p, WIRELINE_OUTLINE, SHEET_OUTLINE_MM, (const double[3]){1, 0, 0}, 1 / sx);
    cairo_restore(cr);
}
