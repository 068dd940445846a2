/* sheet_map.c — a sheet's location map (sheet_map.h). */
#include "sheet/sheet_map.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "page/page.h"
#include "page/page_hillshade.h"
#include "page/page_image.h"
#include "page/page_marks.h"
#include "page/page_placer.h"
#include "page/page_text.h"

#define DEG (M_PI / 180.0)

/* The map's ground window, local metres: [x0, x1] x [y0, y1], and millimetres a metre. */
typedef struct map_window {
    double x0, y0, x1, y1, mm_per_m;
    double px, py;           /* the rectangle's top-left on the page, millimetres */
} map_window;

static void page_xy(const map_window *m, double gx, double gy, double *x, double *y)
{
    *x = m->px + (gx - m->x0) * m->mm_per_m, *y = m->py + (m->y1 - gy) * m->mm_per_m;
}

static map_window window_of(const scene_file *sf, const double eye[2], double x, double y, double w, double h)
{
    double lo[2] = {eye[0], eye[1]}, hi[2] = {eye[0], eye[1]};
    for (uint32_t k = 0; k < sf->n_objects; k++)
        if (sf->objects[k].development)
            for (int i = 0; i < 2; i++)
                lo[i] = fmin(lo[i], sf->objects[k].position[i]), hi[i] = fmax(hi[i], sf->objects[k].position[i]);
    double span = fmax(fmax(hi[0] - lo[0], hi[1] - lo[1]) * 1.4, MAP_MIN_SPAN);
    double mm_per_m = fmin(w, h) / span;
    double cx = 0.5 * (lo[0] + hi[0]), cy = 0.5 * (lo[1] + hi[1]);
    double hw = 0.5 * w / mm_per_m, hh = 0.5 * h / mm_per_m;
    return (map_window){cx - hw, cy - hh, cx + hw, cy + hh, mm_per_m, x, y};
}

/* The hillshade of the surveyed ground, one sample a pixel at dpi (no ground: a blue-grey). */
static int draw_ground(cairo_t *cr, const scene *s, const map_window *m, double w, double h, double dpi,
                       err_buf *err)
{
    int pw = page_pixels(w, dpi), ph = page_pixels(h, dpi);
    float *z = malloc((size_t)pw * ph * sizeof *z);       /* owned here */
    uint8_t *rgb = malloc((size_t)pw * ph * 3);          /* owned here */
    if (!z || !rgb) {
        free(z), free(rgb);
        return err_nomem(err, "out of memory for the location map");
    }
    double step = (m->x1 - m->x0) / pw;
    for (int v = 0; v < ph; v++)
        for (int u = 0; u < pw; u++) {
            double gz;
            int off = scene_surveyed_height(s, m->x0 + (u + 0.5) * step, m->y1 - (v + 0.5) * step, &gz);
            z[(size_t)v * pw + u] = off ? NAN : (float)gz;
        }
    static const uint8_t no_ground[3] = {60, 70, 90};
    for (size_t k = 0; k < (size_t)pw * ph; k++) {
        uint8_t g = isfinite(z[k]) ? page_hillshade(z, (uint32_t)pw, (uint32_t)ph, step, (uint32_t)(k % pw),
                                                    (uint32_t)(k / pw)) : 0;
        for (int c = 0; c < 3; c++) rgb[3 * k + c] = isfinite(z[k]) ? g : no_ground[c];
    }
    cairo_surface_t *img = page_surface_rgb(rgb, pw, ph); /* owned here */
    free(z), free(rgb);
    if (!img) return err_nomem(err, "out of memory for the location map");
    page_paint(cr, img, m->px, m->py, w, h, CAIRO_FILTER_GOOD);
    cairo_surface_destroy(img);
    return 0;
}

/* The frame's field of view: a wedge from the eye along the heading, as far as the nearest
 * structure and a fifth beyond. */
static void draw_wedge(cairo_t *cr, const map_window *m, const sheet_view *v, const double eye[2])
{
    double reach = (isfinite(v->distance_m) ? v->distance_m : 0.5 * (m->x1 - m->x0)) * 1.2;
    double ex, ey;
    page_xy(m, eye[0], eye[1], &ex, &ey);
    cairo_move_to(cr, ex, ey);
    for (int k = 0; k <= 16; k++) {
        double a = (v->heading_deg - 0.5 * v->hfov_deg + v->hfov_deg * k / 16) * DEG, x, y;
        page_xy(m, eye[0] + reach * sin(a), eye[1] + reach * cos(a), &x, &y);
        cairo_line_to(cr, x, y);
    }
    cairo_close_path(cr);
    cairo_set_source_rgba(cr, 1.0, 0.85, 0.2, 0.35);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.75, 0.45, 0.0);
    cairo_set_line_width(cr, 0.3);
    cairo_stroke(cr);
}

/* The development's structures as dots, their names beside them clear of one another, of the
 * viewpoint and of the map's north arrow and scale bar (pl holds those). */
static void draw_structures(cairo_t *cr, const scene_file *sf, const map_window *m, page_placer *pl)
{
    page_font f = {.size_pt = 5.5, .halo = 0.35, .rgb = {0.3, 0.1, 0.45}};
    for (int pass = 0; pass < 2; pass++)
        for (uint32_t k = 0; k < sf->n_objects; k++) {
            const object_spec *o = &sf->objects[k];
            if (!o->development) continue;
            double x, y, w, h;
            page_xy(m, o->position[0], o->position[1], &x, &y);
            if (!pass) {
                page_dot(cr, x, y, 0.9, (const double[3]){0.45, 0.15, 0.65});
                page_placer_mark(pl, x, y, 0.9);
            } else if (o->name) {
                page_text_size(cr, &f, o->name, &w, &h);
                page_box b = page_placer_put(pl, x, y, 0.9, 0.3, w, h);
                page_text(cr, b.x0, b.y0, 0, &f, o->name, 0);
            }
        }
}

static void draw_viewpoint(cairo_t *cr, const map_window *m, const sheet_view *v, const double eye[2])
{
    double x, y;
    page_xy(m, eye[0], eye[1], &x, &y);
    page_dot(cr, x, y, 1.8, (const double[3]){0.8, 0.05, 0.05});
    char n[16];
    if (v->number) snprintf(n, sizeof n, "%u", v->number);
    else snprintf(n, sizeof n, "P"); /* a photograph's camera, no viewpoint of the scene's */
    page_font f = {.size_pt = 5.5, .bold = 1, .align = PAGE_CENTRE, .rgb = {1, 1, 1}};
    page_text(cr, x, y - 1.15, 0, &f, n, 0);
}

int sheet_map_draw(cairo_t *cr, const scene *s, const scene_file *sf, const sheet_view *v, const double eye[2],
                   double x, double y, double w, double h, double dpi, err_buf *err)
{
    map_window m = window_of(sf, eye, x, y, w, h);
    cairo_save(cr);
    cairo_rectangle(cr, x, y, w, h);
    cairo_clip(cr);
    int rc = draw_ground(cr, s, &m, w, h, dpi, err);
    if (!rc) {
        draw_wedge(cr, &m, v, eye);
        page_placer pl; /* owned here */
        page_placer_init(&pl, (page_box){x, y, x + w, y + h});
        page_placer_take(&pl, (page_box){x + w - 10, y, x + w, y + 14});              /* the north arrow */
        page_placer_take(&pl, (page_box){x, y + h - 10, x + 6 + 0.4 * w, y + h});     /* the scale bar */
        double ex, ey;
        page_xy(&m, eye[0], eye[1], &ex, &ey);
        page_placer_mark(&pl, ex, ey, 1.8);
        draw_structures(cr, sf, &m, &pl);
        page_placer_free(&pl);
        draw_viewpoint(cr, &m, v, eye);
        page_north_arrow(cr, x + w - 5, y + 11, 7);
        page_scale_bar(cr, x + 3, y + h - 6, 0.4 * w, m.mm_per_m);
    }
    cairo_restore(cr);
    cairo_rectangle(cr, x, y, w, h);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 0.3);
    cairo_stroke(cr);
    return rc;
}
