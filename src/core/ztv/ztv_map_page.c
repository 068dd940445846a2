/* ztv_map_page.c — a visibility map's page: the map picture, its marks, legend and title block,
 * drawn with the sheets' page layer (page/page.h) in millimetres on A3 landscape (ztv_map.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "page/page.h"
#include "page/page_image.h"
#include "page/page_marks.h"
#include "page/page_placer.h"
#include "page/page_text.h"
#include "ztv/ztv_map.h"
#include "ztv/ztv_map_style.h"
#include "ztv/ztv_summary.h"

#define MARGIN 10.0
#define TITLE_H 16.0
#define EDGE_LABEL 5.0   /* the frame coordinates' strip above and left of the map */
#define PANEL_W 112.0
#define RINGS_MAX 8
#define ZTV_VIEWPOINT_MARK_MM 2.0  /* a viewpoint's dot, radius */
#define ZTV_STRUCTURE_MARK_MM 0.9  /* a structure's dot, radius */

ztv_map_layout ztv_map_layout_of(const ztv_info *info)
{
    const ztv_grid *g = &info->grid;
    double x = MARGIN + EDGE_LABEL, y = MARGIN + TITLE_H + EDGE_LABEL;
    double most_w = ZTV_PAGE_WIDTH - x - 2 * EDGE_LABEL - PANEL_W - MARGIN;
    double most_h = ZTV_PAGE_HEIGHT - y - EDGE_LABEL - MARGIN;
    double gw = g->nx * g->cell, gh = g->ny * g->cell;
    double s = fmin(most_w / gw, most_h / gh);
    return (ztv_map_layout){x, y, gw * s, gh * s, s, g->x0 - 0.5 * g->cell, g->y0 + 0.5 * g->cell};
}

void ztv_map_world_file(const ztv_info *info, double out[6])
{
    ztv_map_layout l = ztv_map_layout_of(info);
    double p = ZTV_MAP_DPI / 25.4, a = 1.0 / (p * l.mm_per_m);
    out[0] = a, out[1] = 0, out[2] = 0, out[3] = -a;
    out[4] = info->origin[0] + l.west + (0.5 / p - l.x) / l.mm_per_m;
    out[5] = info->origin[1] + l.north - (0.5 / p - l.y) / l.mm_per_m;
}

static void to_page(const ztv_map_layout *l, double gx, double gy, double *x, double *y)
{
    *x = l->x + (gx - l->west) * l->mm_per_m, *y = l->y + (l->north - gy) * l->mm_per_m;
}

/* The map picture, one image pixel a reduced-grid pixel; NULL when out of memory. Made once for
 * the page's PDF and PNG; owned by the caller (cairo_surface_destroy). */
static cairo_surface_t *map_picture(const ztv_map *m, const map_style *st)
{
    uint8_t *rgb = malloc((size_t)m->w * m->h * 3); /* owned here */
    if (rgb) ztv_map_colours(m, st, rgb);
    cairo_surface_t *img = rgb ? page_surface_rgb(rgb, (int)m->w, (int)m->h) : NULL;
    free(rgb);
    return img;
}

/* The centre of the rings: the mean of the targets' places. */
static void ring_centre(const ztv_info *info, double c[2])
{
    c[0] = c[1] = 0;
    for (uint32_t t = 0; t < info->n_targets; t++) c[0] += info->target_xy[t][0], c[1] += info->target_xy[t][1];
    c[0] /= info->n_targets, c[1] /= info->n_targets;
}

/* Distance rings round the development: 1, 2, 5, 10, 20, 50 km... inside the radius, labelled
 * (each label taken in pl, for the names to keep off). */
static void draw_rings(cairo_t *cr, const ztv_info *info, const ztv_map_layout *l, page_placer *pl)
{
    if (!info->target_xy || !info->n_targets) return;
    double c[2], x, y;
    ring_centre(info, c);
    to_page(l, c[0], c[1], &x, &y);
    double reach = isfinite(info->radius) ? info->radius : hypot(l->w, l->h) / l->mm_per_m;
    page_font f = {.size_pt = 7, .align = PAGE_CENTRE, .halo = 0.5, .rgb = {0.15, 0.15, 0.15}};
    static const double steps[] = {1000, 2000, 5000, 10000, 20000, 50000, 100000, 200000};
    for (int k = 0; k < RINGS_MAX && steps[k] < reach; k++) {
        double r = steps[k] * l->mm_per_m;
        cairo_new_sub_path(cr);
        cairo_arc(cr, x, y, r, 0, 2 * M_PI);
        cairo_set_source_rgb(cr, 0.15, 0.15, 0.15);
        cairo_set_line_width(cr, 0.3);
        cairo_stroke(cr);
        char text[32];
        page_length_text(steps[k], text, sizeof text);
        double tw, th;
        page_text_size(cr, &f, text, &tw, &th);
        page_placer_take(pl, (page_box){x - tw / 2, y - r - 1.6, x + tw / 2, y - r - 1.6 + th});
        page_text(cr, x, y - r - 1.6, 0, &f, text, 0);
    }
}

/* The radius: the outline of the circles of that radius round every target, dashed. */
static void draw_radius(cairo_t *cr, const ztv_info *info, const ztv_map_layout *l)
{
    if (!isfinite(info->radius) || !info->target_xy) return;
    double r = info->radius;
    cairo_save(cr);
    double dash[2] = {2.0, 1.2};
    cairo_set_dash(cr, dash, 2, 0);
    cairo_set_line_width(cr, 0.45);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    for (uint32_t t = 0; t < info->n_targets; t++) {
        int drawing = 0;
        for (int k = 0; k <= 720; k++) {
            double a = k * M_PI / 360, gx = info->target_xy[t][0] + r * sin(a), gy = info->target_xy[t][1] + r * cos(a);
            int inside = 0;
            for (uint32_t o = 0; o < info->n_targets && !inside; o++)
                inside = o != t && hypot(gx - info->target_xy[o][0], gy - info->target_xy[o][1]) < r - 1e-6 * r;
            double x, y;
            to_page(l, gx, gy, &x, &y);
            if (inside) drawing = 0;
            else if (drawing) cairo_line_to(cr, x, y);
            else cairo_move_to(cr, x, y), drawing = 1;
        }
    }
    cairo_stroke(cr);
    cairo_restore(cr);
}

/* Frame coordinates: ticks every round length along the four edges, eastings above, northings to
 * the left, in the map's CRS. */
static void draw_edges(cairo_t *cr, const ztv_info *info, const ztv_map_layout *l)
{
    double step = page_round_length(l->w / l->mm_per_m / 4), e0 = l->west + info->origin[0],
           n0 = l->north + info->origin[1];
    page_font f = {.size_pt = 6, .align = PAGE_CENTRE, .rgb = {0.2, 0.2, 0.2}};
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_set_line_width(cr, 0.25);
    char text[32];
    for (double e = ceil(e0 / step) * step; e <= e0 + l->w / l->mm_per_m; e += step) {
        double x = l->x + (e - e0) * l->mm_per_m;
        cairo_move_to(cr, x, l->y - 1.5), cairo_line_to(cr, x, l->y + 1.5);
        cairo_move_to(cr, x, l->y + l->h - 1.5), cairo_line_to(cr, x, l->y + l->h + 1.5);
        cairo_stroke(cr);
        snprintf(text, sizeof text, "%.0f", e);
        page_text(cr, x, l->y - EDGE_LABEL + 0.6, 0, &f, text, 0);
        page_text(cr, x, l->y + l->h + 1.2, 0, &f, text, 0);
    }
    for (double n = floor(n0 / step) * step; n >= n0 - l->h / l->mm_per_m; n -= step) {
        double y = l->y + (n0 - n) * l->mm_per_m;
        cairo_move_to(cr, l->x - 1.5, y), cairo_line_to(cr, l->x + 1.5, y);
        cairo_move_to(cr, l->x + l->w - 1.5, y), cairo_line_to(cr, l->x + l->w + 1.5, y);
        cairo_stroke(cr);
        snprintf(text, sizeof text, "%.0f", n);
        for (int side = 0; side < 2; side++) {
            cairo_save(cr);
            cairo_translate(cr, side ? l->x + l->w + EDGE_LABEL - 0.6 : l->x - EDGE_LABEL + 0.6, y);
            cairo_rotate(cr, side ? M_PI / 2 : -M_PI / 2);
            page_text(cr, 0, 0, 0, &f, text, 0);
            cairo_restore(cr);
        }
    }
    cairo_rectangle(cr, l->x, l->y, l->w, l->h);
    cairo_set_line_width(cr, 0.35);
    cairo_stroke(cr);
}

/* The labels of a map, set last over everything else: the text, its font and its box. */
#define LABELS_MAX 512
typedef struct map_labels {
    page_placer placer;
    uint32_t n;
    struct {
        const char *text;
        page_font font;
        page_box box;
    } at[LABELS_MAX];
} map_labels;

/* Places text in font beside the mark of radius r at (x, y). */
static void place_label(cairo_t *cr, map_labels *ml, const char *text, const page_font *f, double x, double y,
                        double r, double gap)
{
    if (!text || !*text || ml->n == LABELS_MAX) return;
    double w, h;
    page_text_size(cr, f, text, &w, &h);
    ml->at[ml->n].text = text, ml->at[ml->n].font = *f;
    ml->at[ml->n].box = page_placer_put(&ml->placer, x, y, r, gap, w, h);
    ml->n++;
}

static void draw_labels(cairo_t *cr, const map_labels *ml)
{
    for (uint32_t k = 0; k < ml->n; k++) {
        page_font f = ml->at[k].font;
        f.align = PAGE_LEFT;
        page_text(cr, ml->at[k].box.x0, ml->at[k].box.y0, 0, &f, ml->at[k].text, 0);
    }
}

/* The outline round development d's targets (their convex hull, by gift wrapping) as a path;
 * its bounds on the page in box. 0 when d has no target. */
static int hull_path(cairo_t *cr, const ztv_info *info, const ztv_map_layout *l, uint32_t d, page_box *box)
{
    uint32_t first = UINT32_MAX, n = 0;
    for (uint32_t t = 0; t < info->n_targets; t++)
        if (info->target_development[t] == d && (first == UINT32_MAX || info->target_xy[t][0] < info->target_xy[first][0]))
            first = t;
    if (first == UINT32_MAX) return 0;
    *box = (page_box){INFINITY, INFINITY, -INFINITY, -INFINITY};
    uint32_t at = first;
    cairo_new_path(cr);
    do {
        double x, y;
        to_page(l, info->target_xy[at][0], info->target_xy[at][1], &x, &y);
        if (n++) cairo_line_to(cr, x, y);
        else cairo_move_to(cr, x, y);
        box->x0 = fmin(box->x0, x), box->y0 = fmin(box->y0, y), box->x1 = fmax(box->x1, x), box->y1 = fmax(box->y1, y);
        uint32_t next = at;
        for (uint32_t t = 0; t < info->n_targets; t++) {
            if (info->target_development[t] != d || t == at) continue;
            const double *a = info->target_xy[at], *b = info->target_xy[next], *c = info->target_xy[t];
            double cross = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
            double ab = hypot(b[0] - a[0], b[1] - a[1]), ac = hypot(c[0] - a[0], c[1] - a[1]);
            if (next == at || cross < 0 || (cross == 0 && ac > ab)) next = t;
        }
        at = next;
    } while (at != first && n <= info->n_targets);
    cairo_close_path(cr);
    return 1;
}

/* Takes the current path (lines) in the placer as marks of radius r every r along it, so that
 * labels keep off the stroke. */
static void take_outline(cairo_t *cr, page_placer *pl, double r)
{
    cairo_path_t *path = cairo_copy_path_flat(cr); /* owned here */
    double first[2] = {0, 0}, at[2] = {0, 0};
    for (int i = 0; i < path->num_data; i += path->data[i].header.length) {
        const cairo_path_data_t *d = &path->data[i];
        double to[2] = {first[0], first[1]};
        if (d->header.type == CAIRO_PATH_MOVE_TO) {
            first[0] = at[0] = d[1].point.x, first[1] = at[1] = d[1].point.y;
            continue;
        }
        if (d->header.type == CAIRO_PATH_LINE_TO) to[0] = d[1].point.x, to[1] = d[1].point.y;
        else if (d->header.type != CAIRO_PATH_CLOSE_PATH) continue;
        double len = hypot(to[0] - at[0], to[1] - at[1]);
        int steps = (int)ceil(len / r);
        for (int k = 0; k <= steps; k++)
            page_placer_mark(pl, at[0] + (to[0] - at[0]) * k / fmax(steps, 1), at[1] + (to[1] - at[1]) * k / fmax(steps, 1), r);
        at[0] = to[0], at[1] = to[1];
    }
    cairo_path_destroy(path);
}

/* Each development: the outline round its structures, each structure a dark dot (each target
 * when the map was given targets alone). The marks are taken in the labels' placer. */
static void draw_developments(cairo_t *cr, const ztv_info *info, const ztv_map_layout *l, map_labels *ml)
{
    if (!info->target_xy) return;
    for (uint32_t d = 0; d < info->n_developments; d++) {
        page_box box;
        if (!hull_path(cr, info, l, d, &box)) continue;
        cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
        cairo_set_source_rgba(cr, 0.45, 0.15, 0.65, 0.9);
        cairo_set_line_width(cr, 2.2); /* the outline stands a millimetre round the structures */
        cairo_stroke_preserve(cr);
        take_outline(cr, &ml->placer, 1.1);
        cairo_new_path(cr);
        if (info->n_structures) continue;
        for (uint32_t t = 0; t < info->n_targets; t++) {
            if (info->target_development[t] != d) continue;
            double x, y;
            to_page(l, info->target_xy[t][0], info->target_xy[t][1], &x, &y);
            page_dot(cr, x, y, ZTV_STRUCTURE_MARK_MM, (const double[3]){0.1, 0.1, 0.1});
            page_placer_mark(&ml->placer, x, y, ZTV_STRUCTURE_MARK_MM);
        }
    }
    for (uint32_t k = 0; k < info->n_structures; k++) {
        double x, y;
        to_page(l, info->structures[k].xy[0], info->structures[k].xy[1], &x, &y);
        page_dot(cr, x, y, ZTV_STRUCTURE_MARK_MM, (const double[3]){0.1, 0.1, 0.1});
        page_placer_mark(&ml->placer, x, y, ZTV_STRUCTURE_MARK_MM);
    }
}

/* The names: each development's beside its outline, then each structure's beside its dot. */
static void label_developments(cairo_t *cr, const ztv_info *info, const ztv_map_layout *l, map_labels *ml)
{
    page_font dev = {.size_pt = 7.5, .bold = 1, .halo = 0.5, .rgb = {0.3, 0.05, 0.4}};
    page_font name = {.size_pt = 6.5, .halo = 0.45, .rgb = {0.1, 0.1, 0.1}};
    for (uint32_t d = 0; info->target_xy && info->development_names && d < info->n_developments; d++) {
        page_box box;
        if (!hull_path(cr, info, l, d, &box)) continue;
        cairo_new_path(cr);
        double r = 0.5 * fmax(box.x1 - box.x0, box.y1 - box.y0) + 1.1; /* past the outline's stroke */
        place_label(cr, ml, info->development_names[d], &dev, 0.5 * (box.x0 + box.x1), 0.5 * (box.y0 + box.y1), r, 0.6);
    }
    for (uint32_t k = 0; k < info->n_structures; k++) {
        double x, y;
        to_page(l, info->structures[k].xy[0], info->structures[k].xy[1], &x, &y);
        place_label(cr, ml, info->structures[k].name, &name, x, y, ZTV_STRUCTURE_MARK_MM, 0.5);
    }
}

/* The viewpoints: a red dot numbered (its name among the labels, beside it). */
static void draw_viewpoints(cairo_t *cr, const ztv_info *info, const ztv_map_layout *l, map_labels *ml)
{
    page_font num = {.size_pt = 6, .bold = 1, .align = PAGE_CENTRE, .rgb = {1, 1, 1}};
    for (uint32_t v = 0; v < info->n_study_views; v++) {
        const ztv_viewpoint *vp = &info->study_views[v];
        double x, y;
        to_page(l, vp->xy[0], vp->xy[1], &x, &y);
        if (x < l->x || x > l->x + l->w || y < l->y || y > l->y + l->h) continue;
        page_dot(cr, x, y, ZTV_VIEWPOINT_MARK_MM, (const double[3]){0.8, 0.05, 0.05});
        page_placer_mark(&ml->placer, x, y, ZTV_VIEWPOINT_MARK_MM);
        char text[16];
        snprintf(text, sizeof text, "%u", vp->number);
        page_text(cr, x, y - 1.25, 0, &num, text, 0);
    }
}

static void label_viewpoints(cairo_t *cr, const ztv_info *info, const ztv_map_layout *l, map_labels *ml)
{
    page_font name = {.size_pt = 6.5, .halo = 0.45, .rgb = {0.55, 0, 0}};
    for (uint32_t v = 0; v < info->n_study_views; v++) {
        const ztv_viewpoint *vp = &info->study_views[v];
        double x, y;
        to_page(l, vp->xy[0], vp->xy[1], &x, &y);
        if (x < l->x || x > l->x + l->w || y < l->y || y > l->y + l->h) continue;
        place_label(cr, ml, vp->name, &name, x, y, ZTV_VIEWPOINT_MARK_MM, 0.6);
    }
}

/* "no terrain" written where the map is past the DTM's edge: at the clear block of such pixels
 * nearest the map's centre. */
static void label_no_terrain(cairo_t *cr, const ztv_map *m, const map_style *st, const ztv_map_layout *l)
{
    const uint8_t *cls = m->cls[st->mode];
    if (!m->class_pixels[st->mode][ZTV_NO_TERRAIN]) return;
    page_font f = {.size_pt = 8, .bold = 1, .align = PAGE_CENTRE, .rgb = {1, 1, 1}};
    const char *text = "no terrain";
    double px_per_mm = m->w / l->w;
    int bw = (int)ceil((page_text_width(cr, &f, text) + 2) * px_per_mm / 2), bh = (int)ceil(2.5 * px_per_mm);
    int best_u = -1, best_v = -1;
    double best = INFINITY;
    int stride = bh > 1 ? bh : 1;
    for (int v = bh; v + bh < (int)m->h; v += stride)
        for (int u = bw; u + bw < (int)m->w; u += stride) {
            double d = hypot(u - 0.5 * m->w, v - 0.5 * m->h);
            if (d >= best || cls[(size_t)v * m->w + u] != ZTV_NO_TERRAIN) continue;
            int clear = 1;
            for (int dv = -bh; dv <= bh && clear; dv++)
                for (int du = -bw; du <= bw && clear; du++) clear = cls[(size_t)(v + dv) * m->w + u + du] == ZTV_NO_TERRAIN;
            if (clear) best = d, best_u = u, best_v = v;
        }
    if (best_u < 0) return;
    double x = l->x + (best_u + 0.5) / px_per_mm, y = l->y + (best_v + 0.5) / px_per_mm;
    page_text(cr, x, y - 1.6, 0, &f, text, 0);
}

/* The legend and the title block in the panel right of the map. */
static void draw_panel(cairo_t *cr, const ztv_map *m, const map_style *st, const ztv_map_layout *l)
{
    const ztv_info *info = m->info;
    double x = l->x + l->w + 2 * EDGE_LABEL, w = ZTV_PAGE_WIDTH - MARGIN - x, y = l->y;
    page_font head = {.size_pt = 8.5, .bold = 1}, text = {.size_pt = 7};
    y += page_text(cr, x, y, w, &head, st->legend_title, 0) + 1.5;
    for (int i = 0; i < st->n_items; i++) {
        uint8_t rgb[3];
        ztv_map_swatch(&st->item[i], rgb);
        cairo_rectangle(cr, x, y, 8, 4);
        cairo_set_source_rgb(cr, rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0);
        cairo_fill_preserve(cr);
        cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
        cairo_set_line_width(cr, 0.2);
        cairo_stroke(cr);
        y += fmax(page_text(cr, x + 10, y + 0.4, w - 10, &text, st->item[i].label, 0), 4) + 1.2;
    }
    y += 1;
    page_dot(cr, x + 4, y + 2, ZTV_VIEWPOINT_MARK_MM, (const double[3]){0.8, 0.05, 0.05});
    y += fmax(page_text(cr, x + 10, y + 0.4, w - 10, &text, "viewpoint, numbered as in the study", 0), 4) + 1.2;
    cairo_rectangle(cr, x + 0.8, y + 0.6, 6.4, 2.8);
    cairo_set_source_rgb(cr, 0.45, 0.15, 0.65);
    cairo_set_line_width(cr, 1.0);
    cairo_stroke(cr);
    page_dot(cr, x + 4, y + 2, ZTV_STRUCTURE_MARK_MM, (const double[3]){0.1, 0.1, 0.1});
    y += fmax(page_text(cr, x + 10, y + 0.4, w - 10, &text, "development: its outline, and each structure named", 0),
              4) + 1.2;
    cairo_new_path(cr);
    cairo_move_to(cr, x, y + 2), cairo_line_to(cr, x + 8, y + 2);
    cairo_set_source_rgb(cr, 0.15, 0.15, 0.15);
    cairo_set_line_width(cr, 0.3);
    cairo_stroke(cr);
    y += fmax(page_text(cr, x + 10, y + 0.4, w - 10, &text, "distance from the development's centre", 0), 4) + 1.2;
    if (isfinite(info->radius)) {
        char r[64], line[128];
        page_length_text(info->radius, r, sizeof r);
        double dash[2] = {2.0, 1.2};
        cairo_save(cr);
        cairo_set_dash(cr, dash, 2, 0);
        cairo_move_to(cr, x, y + 2), cairo_line_to(cr, x + 8, y + 2);
        cairo_set_line_width(cr, 0.45);
        cairo_stroke(cr);
        cairo_restore(cr);
        snprintf(line, sizeof line, "the study radius, %s from the nearest target", r);
        y += fmax(page_text(cr, x + 10, y + 0.4, w - 10, &text, line, 0), 4) + 1.2;
    }
    page_scale_bar(cr, x + 2, y + 4, w - 30, l->mm_per_m);
    page_north_arrow(cr, x + w - 6, y + 12, 9);
    y += 18;
    /* the title block */
    char block[1600], heights[256] = "", radius[64] = "the whole terrain", earth[64] = "off (a flat Earth)";
    size_t used = 0;
    for (uint32_t k = 0; k < info->n_target_heights && used < sizeof heights; k++)
        used += (size_t)snprintf(heights + used, sizeof heights - used, "%s%g", k ? ", " : "", info->target_heights[k]);
    if (isfinite(info->radius)) page_length_text(info->radius, radius, sizeof radius);
    if (info->curvature) snprintf(earth, sizeof earth, "on, refraction k = %g", info->refraction);
    snprintf(block, sizeof block,
             "<b>Project</b>  %s\n<b>Terrain (DTM)</b>  %s\n<b>Date</b>  %s\n<b>Observer</b>  %g m above the ground\n"
             "<b>Targets</b>  %u%s%s%s\n<b>Radius</b>  %s\n<b>Earth curvature</b>  %s\n<b>CRS</b>  %s\n"
             "<b>Grid</b>  %u \u00d7 %u cells of %g m%s",
             info->project ? info->project : "\u2014", info->dtm ? info->dtm : "the scene's terrain",
             info->date ? info->date : "\u2014", info->observer_height, info->n_targets,
             heights[0] ? ", at " : "", heights, heights[0] ? " m above the ground" : "", radius,
             earth, info->crs_name ? info->crs_name : info->crs_wkt ? "unnamed" : "local metres",
             info->grid.nx, info->grid.ny, info->grid.cell, m->step > 1 ? "; drawn one cell in several" : "");
    page_font small = {.size_pt = 6.8};
    double h = page_text(cr, x, y, w - 1, &small, block, 1);
    cairo_rectangle(cr, x - 1.5, y - 1.5, w + 1.5, h + 3);
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    cairo_set_line_width(cr, 0.3);
    cairo_stroke(cr);
}

typedef struct page_ctx {
    const ztv_map *m;
    const map_style *st;
    cairo_surface_t *picture; /* map_picture's; borrowed */
} page_ctx;

static int draw_page(cairo_t *cr, const page_size *size, void *ctx, err_buf *err)
{
    (void)size;
    const page_ctx *c = ctx;
    const ztv_info *info = c->m->info;
    ztv_map_layout l = ztv_map_layout_of(info);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    page_text(cr, MARGIN, MARGIN, 0, &(page_font){.size_pt = 16, .bold = 1}, c->st->title, 0);
    char sub[512];
    snprintf(sub, sizeof sub, "%s%sobserver %g m above the ground, %u target%s", info->project ? info->project : "",
             info->project ? ": " : "", info->observer_height, info->n_targets, info->n_targets == 1 ? "" : "s");
    page_text(cr, MARGIN, MARGIN + 7.5, 0, &(page_font){.size_pt = 8, .rgb = {0.3, 0.3, 0.3}}, sub, 0);
    page_paint(cr, c->picture, l.x, l.y, l.w, l.h, CAIRO_FILTER_NEAREST); /* shown without smoothing */
    cairo_save(cr);
    cairo_rectangle(cr, l.x, l.y, l.w, l.h);
    cairo_clip(cr);
    map_labels *ml = calloc(1, sizeof *ml); /* owned here */
    if (!ml) {
        cairo_restore(cr);
        return err_nomem(err, "out of memory placing a map's labels");
    }
    page_placer_init(&ml->placer, (page_box){l.x, l.y, l.x + l.w, l.y + l.h});
    draw_rings(cr, info, &l, &ml->placer);
    draw_radius(cr, info, &l);
    label_no_terrain(cr, c->m, c->st, &l);
    draw_developments(cr, info, &l, ml);
    draw_viewpoints(cr, info, &l, ml);
    label_viewpoints(cr, info, &l, ml);
    label_developments(cr, info, &l, ml);
    draw_labels(cr, ml);
    page_placer_free(&ml->placer);
    free(ml);
    cairo_restore(cr);
    draw_edges(cr, info, &l);
    draw_panel(cr, c->m, c->st, &l);
    return 0;
}

int ztv_map_page(const ztv_map *m, const map_style *st, FILE *png, FILE *pdf, err_buf *err)
{
    page_size size = {ZTV_PAGE_WIDTH, ZTV_PAGE_HEIGHT, ZTV_MAP_DPI};
    page_ctx c = {m, st, map_picture(m, st)};
    if (!c.picture) return err_nomem(err, "out of memory drawing a %u x %u map", m->w, m->h);
    int rc = page_write_streams(&size, draw_page, &c, pdf, png, err);
    cairo_surface_destroy(c.picture);
    return rc;
}
