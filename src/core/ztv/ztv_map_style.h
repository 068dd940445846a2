/* ztv_map_style.h — inside the visibility maps (ztv_map.h): the reduced grid, what one map shows
 * (its title, legend and the colour of each map pixel, ztv_map.c) and the page that draws it
 * (ztv_map_page.c). Not for use outside src/core/ztv/ztv_map*.c. */
#ifndef SYLVA_ZTV_MAP_STYLE_H
#define SYLVA_ZTV_MAP_STYLE_H

#include <stdint.h>
#include <stdio.h>

#include "util/err.h"
#include "ztv/ztv_raster.h"

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

typedef struct legend_item {
    uint8_t rgb[3];
    int overlay;        /* 1: drawn half-transparent over the hillshade; 2: not computed */
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
     * marks it as not computed. */
    int (*colour)(const struct ztv_map *m, const struct map_style *st, size_t k, uint8_t rgb[3]);
    /* the map before a planting plan at the map's pixels (w * h each), for the map of what the plan
     * hides (ztv_planting_map.c); NULL on every other map. Borrowed. */
    const float *before_fraction;
    const uint8_t *before_cls;
} map_style;

/* The colours of what screening hides: fully, partly, nothing of what was seen. */
extern const uint8_t ztv_map_hidden_rgb[3], ztv_map_partly_hidden_rgb[3], ztv_map_still_visible_rgb[3];

/* The grid row or column that map pixel p samples (the one nearest its centre), of cells. */
uint32_t ztv_map_sampled_cell(const struct ztv_map *m, uint32_t p, uint32_t cells);

/* The legend of a map of what screening hides: labels of the hidden, partly hidden, nothing hidden
 * and nothing seen colours, then the class items of st's mode. */
void ztv_map_add_hidden_items(const struct ztv_map *m, map_style *st, const char *const labels[4]);
/* The colour of a class drawn alike on every map: 2 (opaque) with rgb set, 3 not computed, 0 when
 * the class is open ground. */
int ztv_map_class_colour(uint8_t cls, uint8_t rgb[3]);

/* The colour of every map pixel as st shows it (w * h RGB triples into rgb). */
void ztv_map_colours(const struct ztv_map *m, const map_style *st, uint8_t *rgb);

/* The legend swatch's colour of item it (an overlay over level ground). */
void ztv_map_swatch(const legend_item *it, uint8_t rgb[3]);

/* Draws m as st shows it on a page (ztv_map.h) into png and pdf (open streams; either may be
 * NULL). Returns 0, or -1 with err set. */
int ztv_map_page(const struct ztv_map *m, const map_style *st, FILE *png, FILE *pdf, err_buf *err);

#endif
