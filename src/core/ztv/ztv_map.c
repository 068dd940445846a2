/* ztv_map.c — the reduced grid, its hillshade, and the three kinds of map drawn on it with one
 * frame (title, map, legend panel with scale bar, north arrow and CRS). Nothing here depends on
 * the full grid's size but the reduction step. */
#include "ztv/ztv_map.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sheet/page_hillshade.h"
#include "ztv/ztv_summary.h"

struct ztv_map {
    const ztv_info *info;               /* borrowed */
    uint32_t step;                      /* grid cells per map pixel along each axis */
    uint32_t w, h;                      /* map pixels */
    float *ground;                      /* w * h local heights, NAN where not computed; owned */
    float *fraction[ZTV_MODES];         /* w * h per computed mode; owned */
    uint8_t *cls[ZTV_MODES];            /* w * h ztv_class per computed mode; owned */
    uint32_t *developments[ZTV_MODES];  /* w * h development bits per computed mode; owned */
    uint64_t class_pixels[ZTV_MODES][ZTV_CLASSES]; /* map pixels by class */
};

/* --- the reduced grid ------------------------------------------------------------------------ */

ztv_map *ztv_map_new(const ztv_info *info, err_buf *err)
{
    ztv_map *m = calloc(1, sizeof *m); /* owned by the caller: ztv_map_free */
    if (!m) goto nomem;
    m->info = info;
    uint32_t longest = info->grid.nx > info->grid.ny ? info->grid.nx : info->grid.ny;
    m->step = (longest + ZTV_MAP_MAX_PIXELS - 1) / ZTV_MAP_MAX_PIXELS;
    m->w = (info->grid.nx + m->step - 1) / m->step;
    m->h = (info->grid.ny + m->step - 1) / m->step;
    size_t n = (size_t)m->w * m->h;
    m->ground = malloc(n * sizeof *m->ground);
    if (!m->ground) goto nomem;
    for (size_t k = 0; k < n; k++) m->ground[k] = NAN;
    for (int mode = 0; mode < ZTV_MODES; mode++) {
        if (!info->computed[mode]) continue;
        m->fraction[mode] = calloc(n, sizeof *m->fraction[mode]);
        m->cls[mode] = malloc(n);
        m->developments[mode] = calloc(n, sizeof *m->developments[mode]);
        if (!m->fraction[mode] || !m->cls[mode] || !m->developments[mode]) goto nomem;
        memset(m->cls[mode], ZTV_OUTSIDE, n);
    }
    return m;
nomem:
    ztv_map_free(m);
    err_nomem(err, "out of memory for the visibility map's picture");
    return NULL;
}

void ztv_map_free(ztv_map *m)
{
    if (!m) return;
    free(m->ground);
    for (int mode = 0; mode < ZTV_MODES; mode++) {
        free(m->fraction[mode]);
        free(m->cls[mode]);
        free(m->developments[mode]);
    }
    free(m);
}

/* The grid row or column that map pixel p samples: the one nearest its centre. */
static uint32_t sampled_cell(const ztv_map *m, uint32_t p, uint32_t cells)
{
    uint32_t c = p * m->step + m->step / 2;
    return c < cells ? c : cells - 1;
}

void ztv_map_block(ztv_map *m, const ztv_block *b)
{
    const ztv_grid *g = &m->info->grid;
    for (uint32_t r = 0; r < b->rows; r++) {
        uint32_t j = b->j0 + r, v = j / m->step;
        if (v >= m->h || sampled_cell(m, v, g->ny) != j) continue;
        for (uint32_t u = 0; u < m->w; u++) {
            size_t from = (size_t)r * g->nx + sampled_cell(m, u, g->nx), to = (size_t)v * m->w + u;
            m->ground[to] = b->ground[from];
            for (int mode = 0; mode < ZTV_MODES; mode++) {
                const ztv_layer *l = b->layer[mode];
                if (!m->cls[mode] || !l) continue;
                uint8_t cls = l->cls[from] < ZTV_CLASSES ? l->cls[from] : ZTV_OUTSIDE;
                m->cls[mode][to] = cls;
                m->fraction[mode][to] = l->fraction[from];
                m->developments[mode][to] = l->developments[from];
                m->class_pixels[mode][cls]++;
            }
        }
    }
}

/* --- colours ---------------------------------------------------------------------------------- */

static const uint8_t band_rgb[ZTV_BANDS][3] = {
    {0, 0, 0}, /* 0 %: not drawn */
    {255, 230, 80}, {254, 170, 50}, {240, 100, 30}, {205, 30, 30}, {120, 0, 50}};
static const uint8_t crown_rgb[3] = {30, 100, 45};
static const uint8_t object_rgb[3] = {115, 85, 160};
static const uint8_t outside_rgb[3] = {242, 242, 242}, hatch_rgb[3] = {185, 185, 185};
static const uint8_t no_terrain_rgb[3] = {60, 70, 90};
static const uint8_t hidden_rgb[3] = {25, 80, 200};
static const uint8_t partly_hidden_rgb[3] = {110, 190, 240};
static const uint8_t still_visible_rgb[3] = {255, 215, 90};
/* which developments: one colour each combination of up to three (all of them: red) ... */
static const uint8_t combination_rgb[8][3] = {{0, 0, 0},      {40, 110, 220}, {245, 160, 30},
                                              {150, 60, 180}, {40, 160, 70},  {0, 165, 165},
                                              {225, 100, 160}, {200, 25, 25}};
/* ... or how many, for more */
#define COUNT_CLASSES 7
static const uint8_t count_rgb[COUNT_CLASSES][3] = {{255, 225, 120}, {254, 190, 80}, {250, 145, 50},
                                                    {235, 90, 35},   {205, 35, 35},  {150, 0, 50},
                                                    {80, 0, 70}};
static const uint8_t black[3] = {0, 0, 0}, white[3] = {255, 255, 255}, frame_grey[3] = {90, 90, 90};

static void blend(const uint8_t under[3], const uint8_t over[3], double opacity, uint8_t out[3])
{
    for (int c = 0; c < 3; c++) out[c] = (uint8_t)lround((1 - opacity) * under[c] + opacity * over[c]);
}

/* Light grey with grey diagonals: what was not computed, on the map and in the legend. */
static void hatch(canvas *c, int x0, int y0, int x1, int y1)
{
    for (int y = y0; y <= y1; y++)
        for (int x = x0; x <= x1; x++) canvas_pixel(c, x, y, (x + y) % 8 < 2 ? hatch_rgb : outside_rgb);
}

/* --- hillshade -------------------------------------------------------------------------------- */

/* Grey of map pixel (u, v): the page's hillshade of the reduced grid (sheet/page_hillshade.h). */
static uint8_t hillshade(const ztv_map *m, uint32_t u, uint32_t v)
{
    return page_hillshade(m->ground, m->w, m->h, m->info->grid.cell * m->step, u, v);
}

/* --- what a map shows ------------------------------------------------------------------------- */

typedef struct legend_item {
    uint8_t rgb[3];
    int overlay;        /* 1: drawn half-transparent over the hillshade; 2: hatched (not computed) */
    char label[96];
} legend_item;

#define MAX_ITEMS 16

typedef struct map_style {
    char title[128];
    char legend_title[96];
    legend_item item[MAX_ITEMS];
    int n_items;
    ztv_mode mode;
    /* The colour of map pixel k: 0 leaves the hillshade, 1 lays rgb over it, 2 paints rgb, 3
     * hatches it as not computed. */
    int (*colour)(const ztv_map *m, const struct map_style *st, size_t k, uint8_t rgb[3]);
} map_style;

static void add_item(map_style *st, const uint8_t rgb[3], int overlay, const char *label)
{
    if (st->n_items >= MAX_ITEMS) return;
    legend_item *it = &st->item[st->n_items++];
    memcpy(it->rgb, rgb, 3);
    it->overlay = overlay;
    snprintf(it->label, sizeof it->label, "%s", label);
}

/* Under a crown, inside an object, not computed, no terrain: the same on every map. */
static void add_class_items(const ztv_map *m, map_style *st, ztv_mode mode)
{
    if (m->class_pixels[mode][ZTV_UNDER_CROWN])
        add_item(st, crown_rgb, 0, mode == ZTV_CANOPY ? "under the canopy" : "under a tree crown");
    if (m->class_pixels[mode][ZTV_IN_OBJECT]) add_item(st, object_rgb, 0, "inside an object");
    if (m->class_pixels[mode][ZTV_OUTSIDE]) add_item(st, outside_rgb, 2, "not computed");
    if (m->class_pixels[mode][ZTV_NO_TERRAIN]) add_item(st, no_terrain_rgb, 0, "no terrain (past the DTM's edge)");
}

static int class_colour(uint8_t cls, uint8_t rgb[3])
{
    if (cls == ZTV_UNDER_CROWN) memcpy(rgb, crown_rgb, 3);
    else if (cls == ZTV_IN_OBJECT) memcpy(rgb, object_rgb, 3);
    else if (cls == ZTV_NO_TERRAIN) memcpy(rgb, no_terrain_rgb, 3);
    else if (cls == ZTV_OUTSIDE) return 3;
    else return 0;
    return 2;
}

static int fraction_colour(const ztv_map *m, const map_style *st, size_t k, uint8_t rgb[3])
{
    int cls = class_colour(m->cls[st->mode][k], rgb);
    if (cls) return cls;
    ztv_band band = ztv_band_of(m->fraction[st->mode][k]);
    if (band == ZTV_BAND_NONE) return 0;
    memcpy(rgb, band_rgb[band], 3);
    return 1;
}

static int hidden_colour(const ztv_map *m, const map_style *st, size_t k, uint8_t rgb[3])
{
    if (!ztv_class_on_ground(m->cls[ZTV_BARE][k])) return class_colour(m->cls[ZTV_BARE][k], rgb);
    int cls = class_colour(m->cls[st->mode][k], rgb);
    if (cls) return cls;
    float bare = m->fraction[ZTV_BARE][k], screened = m->fraction[st->mode][k];
    if (!(bare > 0)) return 0;
    if (!(screened > 0)) memcpy(rgb, hidden_rgb, 3);
    else if (screened < bare) memcpy(rgb, partly_hidden_rgb, 3);
    else memcpy(rgb, still_visible_rgb, 3);
    return 1;
}

/* The colour of a combination of developments' bits when there are n <= 3. */
static const uint8_t *combination_colour(uint32_t n, uint32_t bits)
{
    return bits == (1u << n) - 1 ? combination_rgb[7] : combination_rgb[bits];
}

static int popcount(uint32_t x)
{
    int n = 0;
    for (; x; x &= x - 1) n++;
    return n;
}

static int cumulative_colour(const ztv_map *m, const map_style *st, size_t k, uint8_t rgb[3])
{
    int cls = class_colour(m->cls[st->mode][k], rgb);
    if (cls) return cls;
    uint32_t bits = m->developments[st->mode][k];
    if (m->info->n_developments < ZTV_MAX_DEVELOPMENTS) bits &= (1u << m->info->n_developments) - 1;
    if (!bits) return 0;
    if (m->info->n_developments <= 3) memcpy(rgb, combination_colour(m->info->n_developments, bits), 3);
    else memcpy(rgb, count_rgb[popcount(bits) < COUNT_CLASSES ? popcount(bits) - 1 : COUNT_CLASSES - 1], 3);
    return 1;
}

/* --- the frame -------------------------------------------------------------------------------- */

enum { MARGIN = 20, TITLE_SCALE = 3, TEXT_SCALE = 2, PANEL_W = 400, LINE = 20, SWATCH_W = 34,
       SWATCH_H = 20, MARKER_R = 7, TARGET_R = 4 };
#define TOP (MARGIN + 7 * TITLE_SCALE + 10 + 7 * TEXT_SCALE + 16)

typedef struct frame {
    double zoom;          /* canvas pixels per map pixel */
    int map_x, map_y;     /* the map's top-left corner on the canvas */
    int map_w, map_h;     /* its size on the canvas */
    int panel_x;
    double metres_per_px; /* on the canvas */
} frame;

static frame frame_of(const ztv_map *m)
{
    frame f;
    uint32_t longest = m->w > m->h ? m->w : m->h;
    f.zoom = longest < ZTV_MAP_MIN_PIXELS ? (double)ZTV_MAP_MIN_PIXELS / longest : 1;
    f.map_x = MARGIN, f.map_y = TOP;
    f.map_w = (int)lround(m->w * f.zoom), f.map_h = (int)lround(m->h * f.zoom);
    f.panel_x = MARGIN + f.map_w + MARGIN;
    f.metres_per_px = m->info->grid.cell * m->step / f.zoom;
    return f;
}

/* Text in the panel's width, broken at spaces; returns the y below it. c NULL: measures only. */
static int wrapped_text(canvas *c, int x, int y, int width, const char *text, const uint8_t rgb[3])
{
    int per_line = (width + 1) / (6 * TEXT_SCALE);
    char line[256];
    const char *p = text;
    while (*p) {
        int n = (int)strlen(p);
        if (n > per_line) {
            n = per_line;
            while (n > 0 && p[n] != ' ') n--;
            if (n == 0) n = per_line; /* one word longer than the line: cut it */
        }
        if (n > (int)sizeof line - 1) n = (int)sizeof line - 1;
        memcpy(line, p, (size_t)n);
        line[n] = '\0';
        if (c) canvas_text(c, x, y, line, TEXT_SCALE, rgb);
        y += LINE;
        p += n;
        while (*p == ' ') p++;
    }
    return y;
}

/* Text with a white halo, legible over any ground. */
static void halo_text(canvas *c, int x, int y, const char *text)
{
    for (int dy = -2; dy <= 2; dy++)
        for (int dx = -2; dx <= 2; dx++)
            if (dx || dy) canvas_text(c, x + dx, y + dy, text, TEXT_SCALE, white);
    canvas_text(c, x, y, text, TEXT_SCALE, black);
}

static void development_marker(canvas *c, double x, double y)
{
    canvas_disc(c, x, y, MARKER_R, black);
    canvas_disc(c, x, y, MARKER_R - 2, white);
    canvas_disc(c, x, y, 2.5, black);
}

static void filled_triangle(canvas *c, const double p[3][2], const uint8_t rgb[3])
{
    double ymin = fmin(p[0][1], fmin(p[1][1], p[2][1])), ymax = fmax(p[0][1], fmax(p[1][1], p[2][1]));
    for (int y = (int)floor(ymin); y <= (int)ceil(ymax); y++) {
        double yc = y + 0.5, lo = INFINITY, hi = -INFINITY;
        for (int e = 0; e < 3; e++) {
            const double *a = p[e], *b = p[(e + 1) % 3];
            if ((yc < a[1]) == (yc < b[1])) continue;
            double x = a[0] + (yc - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
            lo = fmin(lo, x), hi = fmax(hi, x);
        }
        if (lo <= hi) canvas_rect(c, (int)lround(lo), y, (int)lround(hi) - 1, y, rgb);
    }
}

/* "2 km", "500 m", "1.5 km": a length for a label. */
static void length_text(double metres, char *out, size_t n)
{
    if (metres >= 1000) snprintf(out, n, "%g km", metres / 1000);
    else snprintf(out, n, "%g m", metres);
}

/* The longest round length (1, 2 or 5 times a power of ten) that fits in max_px. */
static double round_length(double metres_per_px, double max_px)
{
    double most = metres_per_px * max_px, best = 0;
    for (double decade = pow(10, floor(log10(most))) / 10; decade <= most; decade *= 10)
        for (int i = 0; i < 3; i++) {
            double len = decade * (i == 0 ? 1 : i == 1 ? 2 : 5);
            if (len <= most) best = len;
        }
    return best;
}

/* The scale bar at (x, y): two halves, black and white, "0", the middle and the length below. */
static int scale_bar(canvas *c, int x, int y, double metres_per_px)
{
    double len = round_length(metres_per_px, PANEL_W - 60);
    int px = (int)lround(len / metres_per_px);
    if (c) {
        canvas_rect(c, x, y, x + px, y + 9, black);
        canvas_rect(c, x + px / 2 + 1, y + 1, x + px - 1, y + 8, white);
        char text[32];
        canvas_text(c, x - 5, y + 14, "0", TEXT_SCALE, black);
        length_text(len, text, sizeof text);
        canvas_text(c, x + px - canvas_text_width(text, TEXT_SCALE) / 2, y + 14, text, TEXT_SCALE, black);
    }
    return y + 14 + LINE;
}

static void north_arrow(canvas *c, int x, int y)
{
    canvas_text(c, x - 5, y, "N", TEXT_SCALE, black);
    const double tip[3][2] = {{x, y + 18}, {x - 9, y + 46}, {x, y + 39}};
    const double right[3][2] = {{x, y + 18}, {x + 9, y + 46}, {x, y + 39}};
    filled_triangle(c, tip, black);
    filled_triangle(c, right, frame_grey);
}

/* The legend panel from y; returns the y below it. c NULL: measures only. */
static int draw_panel(canvas *c, const ztv_map *m, const map_style *st, const frame *f)
{
    const ztv_info *info = m->info;
    int x = f->panel_x, y = f->map_y, width = PANEL_W;
    char text[512];
    y = wrapped_text(c, x, y, width, st->legend_title, black) + 6;
    uint8_t flat[3] = {ZTV_MAP_FLAT_GREY, ZTV_MAP_FLAT_GREY, ZTV_MAP_FLAT_GREY};
    for (int i = 0; i < st->n_items; i++) {
        const legend_item *it = &st->item[i];
        int text_x = x + SWATCH_W + 12;
        if (c) {
            uint8_t rgb[3];
            if (it->overlay == 1) blend(flat, it->rgb, ZTV_MAP_OPACITY, rgb);
            else memcpy(rgb, it->rgb, 3);
            canvas_rect(c, x, y, x + SWATCH_W - 1, y + SWATCH_H - 1, frame_grey);
            if (it->overlay == 2) hatch(c, x + 1, y + 1, x + SWATCH_W - 2, y + SWATCH_H - 2);
            else canvas_rect(c, x + 1, y + 1, x + SWATCH_W - 2, y + SWATCH_H - 2, rgb);
        }
        int below = wrapped_text(c, text_x, y + 3, width - (text_x - x), it->label, black);
        y = (below > y + SWATCH_H + 6 ? below : y + SWATCH_H + 6);
    }
    if (c) development_marker(c, x + SWATCH_W / 2.0, y + SWATCH_H / 2.0);
    y = wrapped_text(c, x + SWATCH_W + 12, y + 3, width - SWATCH_W - 12,
                     info->n_developments > 1 ? "developments" : "the development", black) + 6;
    if (c && info->target_xy) {
        canvas_disc(c, x + SWATCH_W / 2.0, y + SWATCH_H / 2.0, TARGET_R, white);
        canvas_disc(c, x + SWATCH_W / 2.0, y + SWATCH_H / 2.0, TARGET_R - 1, black);
    }
    if (info->target_xy) y = wrapped_text(c, x + SWATCH_W + 12, y + 3, width - SWATCH_W - 12, "targets", black) + 6;
    y += 8;
    snprintf(text, sizeof text, "observer %g m above ground", info->observer_height);
    y = wrapped_text(c, x, y, width, text, black);
    if (isfinite(info->radius)) {
        char radius[64];
        length_text(info->radius, radius, sizeof radius);
        snprintf(text, sizeof text, "radius %s from the targets", radius);
        y = wrapped_text(c, x, y, width, text, black);
    }
    snprintf(text, sizeof text, "%u targets", info->n_targets);
    y = wrapped_text(c, x, y, width, text, black);
    if (info->curvature) snprintf(text, sizeof text, "earth curvature, refraction k = %g", info->refraction);
    else snprintf(text, sizeof text, "no earth curvature");
    y = wrapped_text(c, x, y, width, text, black) + 14;
    y = scale_bar(c, x + 6, y, f->metres_per_px) + 10;
    if (c) north_arrow(c, x + 12, y);
    y += 58;
    snprintf(text, sizeof text, "crs: %s", info->crs_name ? info->crs_name : info->crs_wkt ? "unnamed" : "local metres");
    y = wrapped_text(c, x, y, width, text, black);
    snprintf(text, sizeof text, "grid %u x %u cells of %g m", info->grid.nx, info->grid.ny, info->grid.cell);
    y = wrapped_text(c, x, y, width, text, black);
    if (m->step > 1) {
        snprintf(text, sizeof text, "drawn: one cell in %u x %u", m->step, m->step);
        y = wrapped_text(c, x, y, width, text, black);
    }
    return y;
}

/* The colour of every map pixel (RGB, and 1 in hatched where it is not computed). */
static void map_colours(const ztv_map *m, const map_style *st, uint8_t *rgb, uint8_t *hatched)
{
    for (uint32_t v = 0; v < m->h; v++)
        for (uint32_t u = 0; u < m->w; u++) {
            size_t k = (size_t)v * m->w + u;
            uint8_t *out = rgb + 3 * k, over[3];
            int drawn = isfinite(m->ground[k]) || m->cls[st->mode][k] == ZTV_NO_TERRAIN;
            int how = drawn ? st->colour(m, st, k, over) : 3;
            hatched[k] = how == 3;
            if (how == 3) continue;
            if (how == 2) { /* opaque: no hillshade under it (none past the terrain's edge) */
                memcpy(out, over, 3);
                continue;
            }
            memset(out, hillshade(m, u, v), 3);
            if (how == 1) blend(out, over, ZTV_MAP_OPACITY, out);
        }
}

static int draw_map(const ztv_map *m, const map_style *st, canvas *c, err_buf *err)
{
    const ztv_info *info = m->info;
    frame f = frame_of(m);
    int panel_bottom = draw_panel(NULL, m, st, &f);
    int map_bottom = f.map_y + f.map_h, map_right = f.map_x + f.map_w;
    uint32_t width = (uint32_t)f.panel_x + PANEL_W + MARGIN;
    uint32_t height = (uint32_t)(panel_bottom > map_bottom ? panel_bottom : map_bottom) + MARGIN;
    size_t n = (size_t)m->w * m->h;
    uint8_t *rgb = malloc(n * 4); /* n RGB triples, then n hatched flags; freed below */
    if (!rgb) return err_nomem(err, "out of memory drawing a %u x %u map", m->w, m->h);
    if (canvas_init(c, width, height, white, err)) {
        free(rgb);
        return -1;
    }
    map_colours(m, st, rgb, rgb + 3 * n);
    canvas_text(c, MARGIN, MARGIN, st->title, TITLE_SCALE, black);
    char subtitle[256];
    snprintf(subtitle, sizeof subtitle, "observer %g m above ground, %u target%s%s", info->observer_height,
             info->n_targets, info->n_targets == 1 ? "" : "s",
             info->n_developments > 1 ? ", several developments" : "");
    canvas_text(c, MARGIN, MARGIN + 7 * TITLE_SCALE + 10, subtitle, TEXT_SCALE, frame_grey);
    /* the map, each canvas pixel the map pixel under its centre */
    for (int y = 0; y < f.map_h; y++) {
        uint32_t v = (uint32_t)((y + 0.5) / f.zoom);
        if (v >= m->h) v = m->h - 1;
        for (int x = 0; x < f.map_w; x++) {
            uint32_t u = (uint32_t)((x + 0.5) / f.zoom);
            if (u >= m->w) u = m->w - 1;
            size_t k = (size_t)v * m->w + u;
            int cx = f.map_x + x, cy = f.map_y + y;
            if (rgb[3 * n + k]) hatch(c, cx, cy, cx, cy);
            else canvas_pixel(c, cx, cy, rgb + 3 * k);
        }
    }
    free(rgb);
    canvas_rect(c, f.map_x - 1, f.map_y - 1, map_right, f.map_y - 1, frame_grey);
    canvas_rect(c, f.map_x - 1, map_bottom, map_right, map_bottom, frame_grey);
    canvas_rect(c, f.map_x - 1, f.map_y - 1, f.map_x - 1, map_bottom, frame_grey);
    canvas_rect(c, map_right, f.map_y - 1, map_right, map_bottom, frame_grey);
    double px_per_m = 1.0 / f.metres_per_px;
    double west = info->grid.x0 - 0.5 * info->grid.cell, north = info->grid.y0 + 0.5 * info->grid.cell;
    /* the targets' positions, a dot each (a turbine's hub and blade tips make one), inside the map */
    for (int pass = 0; pass < 2 && info->target_xy; pass++)
        for (uint32_t t = 0; t < info->n_targets; t++) {
            double x = f.map_x + (info->target_xy[t][0] - west) * px_per_m;
            double y = f.map_y + (north - info->target_xy[t][1]) * px_per_m;
            if (x < f.map_x || x > map_right || y < f.map_y || y > map_bottom) continue;
            canvas_disc(c, x, y, pass ? TARGET_R - 1 : TARGET_R, pass ? black : white);
        }
    /* the developments, named when few */
    for (uint32_t d = 0; d < info->n_developments && info->development_xy; d++) {
        double x = f.map_x + (info->development_xy[d][0] - west) * px_per_m;
        double y = f.map_y + (north - info->development_xy[d][1]) * px_per_m;
        development_marker(c, x, y);
    }
    for (uint32_t d = 0; d < info->n_developments && info->development_xy && info->development_names &&
                         info->n_developments <= 12; d++) {
        const char *name = info->development_names[d];
        if (!name || !*name) continue;
        double x = f.map_x + (info->development_xy[d][0] - west) * px_per_m;
        double y = f.map_y + (north - info->development_xy[d][1]) * px_per_m;
        int tw = canvas_text_width(name, TEXT_SCALE);
        int tx = (int)lround(x) + MARKER_R + 5;
        if (tx + tw > map_right) tx = (int)lround(x) - MARKER_R - 5 - tw;
        halo_text(c, tx, (int)lround(y) - 7, name);
    }
    draw_panel(c, m, st, &f);
    return 0;
}

/* --- the three maps --------------------------------------------------------------------------- */

static const char *mode_title(ztv_mode mode)
{
    static const char *const titles[ZTV_MODES] = {"bare earth", "with vegetation", "with vegetation and objects",
                                                  "with the canopy surface"};
    return mode < ZTV_MODES ? titles[mode] : "?";
}

static int mode_missing(const ztv_map *m, ztv_mode mode, err_buf *err)
{
    if (mode < ZTV_MODES && m->cls[mode]) return 0;
    return err_fail(err, ERR_INTERNAL, "the visibility map has no %s results to draw", ztv_mode_name(mode));
}

int ztv_map_draw_mode(const ztv_map *m, ztv_mode mode, canvas *out, err_buf *err)
{
    memset(out, 0, sizeof *out);
    if (mode_missing(m, mode, err)) return -1;
    map_style st = {.mode = mode, .colour = fraction_colour};
    snprintf(st.title, sizeof st.title, "zone of theoretical visibility: %s", mode_title(mode));
    snprintf(st.legend_title, sizeof st.legend_title, "share of the %u target%s visible (%s)",
             m->info->n_targets, m->info->n_targets == 1 ? "" : "s", mode_title(mode));
    for (int band = ZTV_BAND_ALL; band > ZTV_BAND_NONE; band--) {
        char label[32];
        snprintf(label, sizeof label, "%s %%", ztv_band_label((ztv_band)band));
        add_item(&st, band_rgb[band], 1, label);
    }
    uint8_t flat[3] = {ZTV_MAP_FLAT_GREY, ZTV_MAP_FLAT_GREY, ZTV_MAP_FLAT_GREY};
    add_item(&st, flat, 0, "0 % (not visible)");
    add_class_items(m, &st, mode);
    return draw_map(m, &st, out, err);
}

int ztv_map_draw_hidden(const ztv_map *m, ztv_mode mode, canvas *out, err_buf *err)
{
    memset(out, 0, sizeof *out);
    if (mode_missing(m, ZTV_BARE, err) || mode_missing(m, mode, err)) return -1;
    map_style st = {.mode = mode, .colour = hidden_colour};
    snprintf(st.title, sizeof st.title, "visibility hidden by screening: %s", mode_title(mode));
    snprintf(st.legend_title, sizeof st.legend_title, "bare earth against %s", mode_title(mode));
    add_item(&st, hidden_rgb, 1, "visible on bare earth, fully hidden");
    add_item(&st, partly_hidden_rgb, 1, "visible on bare earth, partly hidden");
    add_item(&st, still_visible_rgb, 1, "visible, nothing hidden");
    uint8_t flat[3] = {ZTV_MAP_FLAT_GREY, ZTV_MAP_FLAT_GREY, ZTV_MAP_FLAT_GREY};
    add_item(&st, flat, 0, "not visible on bare earth");
    add_class_items(m, &st, mode);
    return draw_map(m, &st, out, err);
}

/* "A only", "A + B": the developments of a combination of bits. */
static void combination_label(const ztv_info *info, uint32_t bits, char *out, size_t n)
{
    out[0] = '\0';
    size_t used = 0;
    for (uint32_t d = 0; d < info->n_developments; d++) {
        if (!(bits >> d & 1u)) continue;
        const char *name = info->development_names && info->development_names[d] ? info->development_names[d] : "?";
        int k = snprintf(out + used, n - used, "%s%s", used ? " + " : "", name);
        if (k < 0 || (size_t)k >= n - used) return;
        used += (size_t)k;
    }
    if (popcount(bits) == 1 && used + 6 < n) strcat(out, " only");
}

int ztv_map_draw_cumulative(const ztv_map *m, ztv_mode mode, canvas *out, err_buf *err)
{
    memset(out, 0, sizeof *out);
    if (mode_missing(m, mode, err)) return -1;
    map_style st = {.mode = mode, .colour = cumulative_colour};
    uint32_t n = m->info->n_developments;
    snprintf(st.title, sizeof st.title, "cumulative visibility: %s", mode_title(mode));
    char label[96];
    if (n <= 3) {
        snprintf(st.legend_title, sizeof st.legend_title, "developments visible (%s)", mode_title(mode));
        for (uint32_t bits = (1u << n) - 1; bits >= 1; bits--) {
            combination_label(m->info, bits, label, sizeof label);
            add_item(&st, combination_colour(n, bits), 1, label);
        }
    } else {
        snprintf(st.legend_title, sizeof st.legend_title, "how many of the %u developments are visible (%s)",
                 n, mode_title(mode));
        int classes = n < COUNT_CLASSES ? (int)n : COUNT_CLASSES;
        for (int i = classes - 1; i >= 0; i--) {
            if (i == COUNT_CLASSES - 1 && n > COUNT_CLASSES) snprintf(label, sizeof label, "%d or more", i + 1);
            else snprintf(label, sizeof label, "%d", i + 1);
            add_item(&st, count_rgb[i], 1, label);
        }
    }
    uint8_t flat[3] = {ZTV_MAP_FLAT_GREY, ZTV_MAP_FLAT_GREY, ZTV_MAP_FLAT_GREY};
    add_item(&st, flat, 0, "none");
    add_class_items(m, &st, mode);
    return draw_map(m, &st, out, err);
}
