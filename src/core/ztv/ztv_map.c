/* ztv_map.c — the reduced grid, its hillshade, and the three kinds of map drawn on it with one
 * frame (title, map, legend panel with scale bar, north arrow and CRS; a planting plan's map is
 * ztv_map_planting.c's). Nothing here depends on the full grid's size but the reduction step. */
#include "ztv/ztv_map.h"
#include "ztv/ztv_map_style.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "page/page_hillshade.h"
#include "ztv/ztv_summary.h"


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

uint32_t ztv_map_sampled_cell(const ztv_map *m, uint32_t p, uint32_t cells)
{
    uint32_t c = p * m->step + m->step / 2;
    return c < cells ? c : cells - 1;
}

void ztv_map_block(ztv_map *m, const ztv_block *b)
{
    const ztv_grid *g = &m->info->grid;
    for (uint32_t r = 0; r < b->rows; r++) {
        uint32_t j = b->j0 + r, v = j / m->step;
        if (v >= m->h || ztv_map_sampled_cell(m, v, g->ny) != j) continue;
        for (uint32_t u = 0; u < m->w; u++) {
            size_t from = (size_t)r * g->nx + ztv_map_sampled_cell(m, u, g->nx), to = (size_t)v * m->w + u;
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
static const uint8_t outside_rgb[3] = {242, 242, 242};
static const uint8_t no_terrain_rgb[3] = {60, 70, 90};
const uint8_t ztv_map_hidden_rgb[3] = {25, 80, 200};
const uint8_t ztv_map_partly_hidden_rgb[3] = {110, 190, 240};
const uint8_t ztv_map_still_visible_rgb[3] = {255, 215, 90};
/* which developments: one colour each combination of up to three (all of them: red) ... */
static const uint8_t combination_rgb[8][3] = {{0, 0, 0},      {40, 110, 220}, {245, 160, 30},
                                              {150, 60, 180}, {40, 160, 70},  {0, 165, 165},
                                              {225, 100, 160}, {200, 25, 25}};
/* ... or how many, for more */
#define COUNT_CLASSES 7
static const uint8_t count_rgb[COUNT_CLASSES][3] = {{255, 225, 120}, {254, 190, 80}, {250, 145, 50},
                                                    {235, 90, 35},   {205, 35, 35},  {150, 0, 50},
                                                    {80, 0, 70}};

static void blend(const uint8_t under[3], const uint8_t over[3], double opacity, uint8_t out[3])
{
    for (int c = 0; c < 3; c++) out[c] = (uint8_t)lround((1 - opacity) * under[c] + opacity * over[c]);
}

/* --- hillshade -------------------------------------------------------------------------------- */

/* Grey of map pixel (u, v): the page's hillshade of the reduced grid (page/page.hillshade.h). */
static uint8_t hillshade(const ztv_map *m, uint32_t u, uint32_t v)
{
    return page_hillshade(m->ground, m->w, m->h, m->info->grid.cell * m->step, u, v);
}

/* --- what a map shows ------------------------------------------------------------------------- */


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

void ztv_map_add_hidden_items(const ztv_map *m, map_style *st, const char *const labels[4])
{
    add_item(st, ztv_map_hidden_rgb, 1, labels[0]);
    add_item(st, ztv_map_partly_hidden_rgb, 1, labels[1]);
    add_item(st, ztv_map_still_visible_rgb, 1, labels[2]);
    uint8_t flat[3] = {ZTV_MAP_FLAT_GREY, ZTV_MAP_FLAT_GREY, ZTV_MAP_FLAT_GREY};
    add_item(st, flat, 0, labels[3]);
    add_class_items(m, st, st->mode);
}

int ztv_map_class_colour(uint8_t cls, uint8_t rgb[3])
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
    int cls = ztv_map_class_colour(m->cls[st->mode][k], rgb);
    if (cls) return cls;
    ztv_band band = ztv_band_of(m->fraction[st->mode][k]);
    if (band == ZTV_BAND_NONE) return 0;
    memcpy(rgb, band_rgb[band], 3);
    return 1;
}

static int hidden_colour(const ztv_map *m, const map_style *st, size_t k, uint8_t rgb[3])
{
    if (!ztv_class_on_ground(m->cls[ZTV_BARE][k])) return ztv_map_class_colour(m->cls[ZTV_BARE][k], rgb);
    int cls = ztv_map_class_colour(m->cls[st->mode][k], rgb);
    if (cls) return cls;
    float bare = m->fraction[ZTV_BARE][k], screened = m->fraction[st->mode][k];
    if (!(bare > 0)) return 0;
    if (!(screened > 0)) memcpy(rgb, ztv_map_hidden_rgb, 3);
    else if (screened < bare) memcpy(rgb, ztv_map_partly_hidden_rgb, 3);
    else memcpy(rgb, ztv_map_still_visible_rgb, 3);
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
    int cls = ztv_map_class_colour(m->cls[st->mode][k], rgb);
    if (cls) return cls;
    uint32_t bits = m->developments[st->mode][k];
    if (m->info->n_developments < ZTV_MAX_DEVELOPMENTS) bits &= (1u << m->info->n_developments) - 1;
    if (!bits) return 0;
    if (m->info->n_developments <= 3) memcpy(rgb, combination_colour(m->info->n_developments, bits), 3);
    else memcpy(rgb, count_rgb[popcount(bits) < COUNT_CLASSES ? popcount(bits) - 1 : COUNT_CLASSES - 1], 3);
    return 1;
}

void ztv_map_swatch(const legend_item *it, uint8_t rgb[3])
{
    const uint8_t flat[3] = {ZTV_MAP_FLAT_GREY, ZTV_MAP_FLAT_GREY, ZTV_MAP_FLAT_GREY};
    if (it->overlay == 1) blend(flat, it->rgb, ZTV_MAP_OPACITY, rgb);
    else memcpy(rgb, it->rgb, 3);
}

void ztv_map_colours(const ztv_map *m, const map_style *st, uint8_t *rgb)
{
    for (uint32_t v = 0; v < m->h; v++)
        for (uint32_t u = 0; u < m->w; u++) {
            size_t k = (size_t)v * m->w + u;
            uint8_t *out = rgb + 3 * k, over[3];
            int drawn = isfinite(m->ground[k]) || m->cls[st->mode][k] == ZTV_NO_TERRAIN;
            int how = drawn ? st->colour(m, st, k, over) : 3;
            if (how == 3) { /* not computed */
                memcpy(out, outside_rgb, 3);
                continue;
            }
            if (how == 2) { /* opaque: no hillshade under it (none past the terrain's edge) */
                memcpy(out, over, 3);
                continue;
            }
            memset(out, hillshade(m, u, v), 3);
            if (how == 1) blend(out, over, ZTV_MAP_OPACITY, out);
        }
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

int ztv_map_write_mode(const ztv_map *m, ztv_mode mode, FILE *png, FILE *pdf, err_buf *err)
{
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
    return ztv_map_page(m, &st, png, pdf, err);
}

int ztv_map_write_hidden(const ztv_map *m, ztv_mode mode, FILE *png, FILE *pdf, err_buf *err)
{
    if (mode_missing(m, ZTV_BARE, err) || mode_missing(m, mode, err)) return -1;
    map_style st = {.mode = mode, .colour = hidden_colour};
    snprintf(st.title, sizeof st.title, "visibility hidden by screening: %s", mode_title(mode));
    snprintf(st.legend_title, sizeof st.legend_title, "bare earth against %s", mode_title(mode));
    const char *labels[4] = {"visible on bare earth, fully hidden", "visible on bare earth, partly hidden",
                             "visible, nothing hidden", "not visible on bare earth"};
    ztv_map_add_hidden_items(m, &st, labels);
    return ztv_map_page(m, &st, png, pdf, err);
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

int ztv_map_write_cumulative(const ztv_map *m, ztv_mode mode, FILE *png, FILE *pdf, err_buf *err)
{
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
    return ztv_map_page(m, &st, png, pdf, err);
}
