/* sheet.c — a sheet's page laid out and written (sheet.h). */
#include "sheet/sheet.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "page/page_text.h"
#include "sheet/sheet_map.h"
#include "sheet/sheet_table.h"
#include "sheet/sheet_wireline.h"

#define MARGIN 10.0     /* laid-out millimetres, A3 */
#define GAP 6.0
#define TITLE_H 16.0
#define CAPTION_H 4.5
#define FOOT_H 9.0
#define RIGHT_MIN 140.0 /* the right column, for the map and the table */
#define WIDE_ASPECT 0.45 /* a frame less high than this for its width is laid out as a panorama */
#define SIDE_WIDE 128.0  /* a panorama's existing view and wireline, wide */
/* the panels' captions: a study's rendered views, or a photomontage and its photograph */
#define PROPOSED(sh) ((sh)->photo ? "Photomontage (proposed)" : "Proposed view")
#define EXISTING(sh) ((sh)->photo ? "Existing view (the photograph)" : "Existing view")

page_size sheet_page_size(double print_width_mm, double dpi)
{
    double w = print_width_mm > 0 ? print_width_mm : SHEET_A3_WIDTH;
    return (page_size){w, w * SHEET_A3_HEIGHT / SHEET_A3_WIDTH, dpi > 0 ? dpi : 300.0};
}

/* The panels' sizes: the proposed view as wide as the left column allows and the page's height
 * holds with the two smaller ones under it. */
static sheet_panels panels_of(double aspect)
{
    double avail_h = SHEET_A3_HEIGHT - 2 * MARGIN - TITLE_H - 2 * CAPTION_H - GAP - FOOT_H;
    double left = SHEET_A3_WIDTH - 2 * MARGIN - GAP - RIGHT_MIN;
    /* main * aspect + (main - GAP) / 2 * aspect <= avail_h */
    double main = fmin(left, (avail_h + 0.5 * GAP * aspect) / (1.5 * aspect));
    sheet_panels p = {.main_mm = main, .side_mm = 0.5 * (main - GAP)};
    p.height_main_mm = main * aspect, p.height_side_mm = p.side_mm * aspect;
    return p;
}

/* A panorama's panels: the proposed view across the page, the two others SIDE_WIDE wide. */
static sheet_panels wide_panels_of(double aspect)
{
    sheet_panels p = {.main_mm = SHEET_A3_WIDTH - 2 * MARGIN, .side_mm = SIDE_WIDE};
    p.height_main_mm = p.main_mm * aspect, p.height_side_mm = p.side_mm * aspect;
    return p;
}

typedef struct draw_ctx {
    const sheet *sh;
    double scale;           /* printed millimetres per laid-out millimetre */
} draw_ctx;

static void draw_title(cairo_t *cr, const sheet *sh)
{
    const sheet_view *v = &sh->view;
    char title[256], project[512];
    char planting[160];
    if (sh->photo) snprintf(title, sizeof title, "Photomontage: %s", sh->photo->file);
    else if (sheet_planting_text(sh, planting, sizeof planting))
        snprintf(title, sizeof title, "Viewpoint %u: %s \u2014 %s", v->number, v->name, planting);
    else
        snprintf(title, sizeof title, "Viewpoint %u: %s", v->number, v->name);
    page_font big = {.size_pt = 16, .bold = 1};
    page_text(cr, MARGIN, MARGIN, 0, &big, title, 0);
    page_font small = {.size_pt = 8, .rgb = {0.25, 0.25, 0.25}};
    const char *base = strrchr(sh->sf->path, '/');
    if (sh->photo)
        snprintf(project, sizeof project, "%s, %.1f\u00b0 across \u2014 photograph, photomontage and wireline",
                 v->frame, v->hfov_deg);
    else
        snprintf(project, sizeof project, "%s frame, %.1f\u00b0 across \u2014 existing view, proposed view and wireline",
                 v->frame, v->hfov_deg);
    page_text(cr, MARGIN, MARGIN + 7.5, 0, &small, project, 0);
    snprintf(project, sizeof project, "Project: %s", base ? base + 1 : sh->sf->path);
    page_font right = {.size_pt = 9, .bold = 1, .align = PAGE_RIGHT};
    page_text(cr, SHEET_A3_WIDTH - MARGIN, MARGIN, 0, &right, project, 0);
    right.bold = 0, right.size_pt = 8;
    char type[64];
    snprintf(type, sizeof type, "Visualisation Type %d (LI TGN 06/19)", sh->photo ? sh->photo->type : 2);
    page_text(cr, SHEET_A3_WIDTH - MARGIN, MARGIN + 5, 0, &right, type, 0);
    cairo_move_to(cr, MARGIN, MARGIN + TITLE_H - 3);
    cairo_line_to(cr, SHEET_A3_WIDTH - MARGIN, MARGIN + TITLE_H - 3);
    cairo_set_line_width(cr, 0.35);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_stroke(cr);
}

/* A picture with its caption above it; a grey box saying so when the study did not make it. */
static int draw_panel(cairo_t *cr, const page_picture *p, const char *caption, double x, double y, double w, double h,
                      double dpi, err_buf *err)
{
    page_font f = {.size_pt = 8, .bold = 1};
    page_text(cr, x, y, 0, &f, caption, 0);
    y += CAPTION_H;
    if (p->rgb && page_image(cr, p, x, y, w, h, dpi, err)) return -1;
    cairo_rectangle(cr, x, y, w, h);
    if (!p->rgb) {
        cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
        cairo_fill_preserve(cr);
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 0.25);
    cairo_stroke(cr);
    return 0;
}

/* The wireline's panel: the existing view with the wireline stroked over it (sheet_wireline.h). */
static int draw_wireline(cairo_t *cr, const sheet *sh, double x, double y, double w, double h, double dpi,
                         err_buf *err)
{
    page_picture none = {0};
    const char *caption = sh->photo ? "Wireline over the photograph" : "Wireline";
    if (draw_panel(cr, sh->wireline ? &sh->existing : &none, caption, x, y, w, h, dpi, err)) return -1;
    sheet_wireline_draw(cr, sh->wireline, x, y + CAPTION_H, w, h);
    return 0;
}

static double draw_table(cairo_t *cr, const sheet *sh, const sheet_panels *p, double scale, double x, double y,
                         double w)
{
    sheet_row rows[SHEET_ROWS_MAX];
    uint32_t n = sheet_table(sh, p, scale, rows);
    page_font label = {.size_pt = 6.5, .bold = 1}, text = {.size_pt = 6.5};
    double label_w = 36;
    for (uint32_t k = 0; k < n; k++) {
        double h1 = page_text(cr, x, y, label_w - 1, &label, rows[k].label, 0);
        double h2 = page_text(cr, x + label_w, y, w - label_w, &text, rows[k].text, 0);
        y += fmax(h1, h2) + 0.6;
    }
    return y;
}

static void draw_foot(cairo_t *cr, const sheet *sh)
{
    char note[640];
    if (sh->photo)
        snprintf(note, sizeof note,
                 "Printed at 100%% on %s paper, each picture shows the landscape at its true size when held at the "
                 "distance given for it and seen with one eye. The photomontage is the photograph with the development "
                 "rendered into it by sylva through the camera %s, the terrain and vegetation in front of it hiding it "
                 "and its shadows darkening the photograph; the wireline is the development's outline (red) and inner "
                 "edges (yellow) as that camera sees them, over the photograph.",
                 sh->page.width_mm == SHEET_A3_WIDTH ? "A3" : "the stated",
                 sh->photo->points ? "matched to the control points" : "the scene gives");
    else
        snprintf(note, sizeof note,
                 "Printed at 100%% on %s paper, each view shows the landscape at its true size when held at the distance "
                 "given for it and seen with one eye. Rendered by sylva from the scene's terrain model, vegetation and "
                 "development; the wireline is the development's outline (red) and inner edges (yellow) as the camera sees "
                 "them, over the existing view.",
                 sh->page.width_mm == SHEET_A3_WIDTH ? "A3" : "the stated");
    page_font f = {.size_pt = 6, .rgb = {0.2, 0.2, 0.2}};
    page_text(cr, MARGIN, SHEET_A3_HEIGHT - MARGIN - FOOT_H + 2, SHEET_A3_WIDTH - 2 * MARGIN, &f, note, 0);
}

/* A frame taller than a panorama: the proposed view large at the left, the existing view and the
 * wireline under it, the map and the table in the right column. */
static int draw_upright(cairo_t *cr, const sheet *sh, const sheet_panels *p, double scale, double dpi, err_buf *err)
{
    double x = MARGIN, y = MARGIN + TITLE_H;
    if (draw_panel(cr, &sh->proposed, PROPOSED(sh), x, y, p->main_mm, p->height_main_mm, dpi, err)) return -1;
    y += CAPTION_H + p->height_main_mm + GAP;
    if (draw_panel(cr, &sh->existing, EXISTING(sh), x, y, p->side_mm, p->height_side_mm, dpi, err) ||
        draw_wireline(cr, sh, x + p->side_mm + GAP, y, p->side_mm, p->height_side_mm, dpi, err))
        return -1;
    double rx = MARGIN + p->main_mm + GAP, rw = SHEET_A3_WIDTH - MARGIN - rx, ry = MARGIN + TITLE_H;
    double map_h = fmin(rw * 0.72, 0.42 * (SHEET_A3_HEIGHT - ry));
    page_font cap = {.size_pt = 8, .bold = 1};
    page_text(cr, rx, ry, 0, &cap, "Location", 0);
    if (sheet_map_draw(cr, sh->s, sh->sf, &sh->view, sh->eye, rx, ry + CAPTION_H, rw, map_h, dpi, err)) return -1;
    draw_table(cr, sh, p, scale, rx, ry + CAPTION_H + map_h + 3, rw);
    return 0;
}

/* A panorama: the proposed view across the page, under it the existing view over the wireline,
 * the map and the table side by side. */
static int draw_wide(cairo_t *cr, const sheet *sh, const sheet_panels *p, double scale, double dpi, err_buf *err)
{
    double x = MARGIN, y = MARGIN + TITLE_H;
    if (draw_panel(cr, &sh->proposed, PROPOSED(sh), x, y, p->main_mm, p->height_main_mm, dpi, err)) return -1;
    y += CAPTION_H + p->height_main_mm + GAP;
    if (draw_panel(cr, &sh->existing, EXISTING(sh), x, y, p->side_mm, p->height_side_mm, dpi, err) ||
        draw_wireline(cr, sh, x, y + CAPTION_H + p->height_side_mm + GAP, p->side_mm, p->height_side_mm, dpi, err))
        return -1;
    double mx = x + p->side_mm + GAP, mh = SHEET_A3_HEIGHT - MARGIN - FOOT_H - y - CAPTION_H, mw = fmin(mh * 1.1, 110);
    page_font cap = {.size_pt = 8, .bold = 1};
    page_text(cr, mx, y, 0, &cap, "Location", 0);
    if (sheet_map_draw(cr, sh->s, sh->sf, &sh->view, sh->eye, mx, y + CAPTION_H, mw, mh, dpi, err)) return -1;
    double tx = mx + mw + GAP;
    draw_table(cr, sh, p, scale, tx, y, SHEET_A3_WIDTH - MARGIN - tx);
    return 0;
}

static int draw_sheet(cairo_t *cr, const page_size *size, void *ctx, err_buf *err)
{
    const draw_ctx *d = ctx;
    const sheet *sh = d->sh;
    cairo_scale(cr, d->scale, d->scale);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    double dpi = size->dpi * d->scale; /* pixels per laid-out inch */
    double aspect = (double)sh->view.height / sh->view.width;
    int wide = aspect < WIDE_ASPECT;
    sheet_panels p = wide ? wide_panels_of(aspect) : panels_of(aspect);
    draw_title(cr, sh);
    if (wide ? draw_wide(cr, sh, &p, d->scale, dpi, err) : draw_upright(cr, sh, &p, d->scale, dpi, err)) return -1;
    draw_foot(cr, sh);
    return 0;
}

int sheet_write(const sheet *sh, const char *pdf_path, const char *png_path, err_buf *err)
{
    draw_ctx d = {sh, sh->page.width_mm / SHEET_A3_WIDTH};
    return page_write(&sh->page, draw_sheet, &d, pdf_path, png_path, err);
}
