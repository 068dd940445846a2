/* ztv_map.h — the visibility maps as pages for a reader (docs/ztv.md, "Maps"): a reduced copy of
 * the grid kept as the blocks of rows arrive (at most ZTV_MAP_MAX_PIXELS on the long side, the
 * cell nearest each pixel's centre), drawn at the end on an A3 landscape page (ztv_map_page.c,
 * with page/page.h: a vector PDF and a PNG at ZTV_MAP_DPI) as a hillshade of the terrain (sun from
 * the north-west, 45 degrees up) under half-transparent colour bands, with the viewpoints plotted
 * and numbered, distance rings round the development, the radius, frame coordinates along the
 * edges, each development's outline and name and its structures marked and named (page/page_placer.h
 * keeps the names clear of one another), "no terrain" past the DTM's edge,
 * a legend, a scale bar, a north arrow and a title block (project, DTM, date, observer and target
 * heights, curvature, CRS). Beside each PNG its world file (ztv_map_world_file) places the page's
 * pixels in the site's CRS.
 *
 * Ownership: ztv_map_new returns a map that ztv_map_free releases; it keeps info, which must
 * outlive it. Each write draws into streams the caller owns. */
#ifndef SYLVA_ZTV_MAP_H
#define SYLVA_ZTV_MAP_H

#include <stdint.h>
#include <stdio.h>

#include "page/page_hillshade.h"
#include "util/err.h"
#include "ztv/ztv_raster.h"

#define ZTV_MAP_MAX_PIXELS 1600u /* map pixels on the grid's long side, at most */
#define ZTV_MAP_DPI 150.0        /* the PNG's pixels per inch (the PDF's map picture is the reduced grid) */
#define ZTV_MAP_FLAT_GREY HILLSHADE_FLAT_GREY /* the hillshade of level ground */
#define ZTV_MAP_OPACITY 0.65     /* of the colour bands over the hillshade */

typedef struct ztv_map ztv_map;

ztv_map *ztv_map_new(const ztv_info *info, err_buf *err); /* NULL with err set */
void ztv_map_free(ztv_map *m);                            /* accepts NULL */
/* Keeps the block's cells that fall on map pixels (the caller checked the block). */
void ztv_map_block(ztv_map *m, const ztv_block *b);

/* Each writes its map page as a PNG into png and a PDF into pdf (either may be NULL). Returns 0, or
 * -1 with err set. */
/* The visible fraction of the development in mode (ztv_MODE.png, .pdf). */
int ztv_map_write_mode(const ztv_map *m, ztv_mode mode, FILE *png, FILE *pdf, err_buf *err);
/* Where the screening of mode hides what bare earth shows (ztv_hidden_MODE.png, .pdf). */
int ztv_map_write_hidden(const ztv_map *m, ztv_mode mode, FILE *png, FILE *pdf, err_buf *err);
/* What a planting plan hides in mode at its year (ztv_hidden_by_planting.png, .pdf): m is the
 * year's map, its info's planting_before the folder of the map made before the plan on the same
 * grid (ztv_map_planting.c). */
int ztv_map_write_planting(const ztv_map *m, ztv_mode mode, FILE *png, FILE *pdf, err_buf *err);
/* Which developments are visible from each cell in mode (ztv_cumulative_MODE.png, .pdf). */
int ztv_map_write_cumulative(const ztv_map *m, ztv_mode mode, FILE *png, FILE *pdf, err_buf *err);

/* Where the map of a grid lies on its page: the map's rectangle in millimetres and its scale. */
typedef struct ztv_map_layout {
    double x, y, w, h;       /* millimetres from the page's top-left corner */
    double mm_per_m;
    double west, north;      /* local coordinates of the map's top-left corner */
} ztv_map_layout;
#define ZTV_PAGE_WIDTH 420.0
#define ZTV_PAGE_HEIGHT 297.0
ztv_map_layout ztv_map_layout_of(const ztv_info *info);

/* The six numbers of the page PNG's world file (ztv_MODE.pgw, ESRI's order: A, D, B, E, C, F), so
 * that map easting = A col + C and northing = E row + F at the centre of pixel (col, row): with
 * p = ZTV_MAP_DPI / 25.4 pixels a millimetre, A = 1 / (p mm_per_m), E = -A, C = origin east + west +
 * (0.5 / p - x) / mm_per_m and F = origin north + north - (0.5 / p - y) / mm_per_m. */
void ztv_map_world_file(const ztv_info *info, double out[6]);

#endif
