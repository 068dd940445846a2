/* ztv_map.h — the visibility maps as pictures for a reader: a reduced copy of the grid kept as
 * the blocks of rows arrive (at most ZTV_MAP_MAX_PIXELS on the long side, the cell nearest each
 * pixel's centre), drawn at the end as a hillshade of the terrain (sun from the north-west, 45
 * degrees up) under half-transparent colour bands, with a legend, the developments' positions,
 * a scale bar, a north arrow and the CRS (docs/ztv.md, "Outputs").
 *
 * Ownership: ztv_map_new returns a map that ztv_map_free releases; it keeps info, which must
 * outlive it. Each draw fills a canvas the caller frees (canvas_free). */
#ifndef SYLVA_ZTV_MAP_H
#define SYLVA_ZTV_MAP_H

#include <stdint.h>

#include "io/raster_canvas.h"
#include "sheet/page_hillshade.h"
#include "util/err.h"
#include "ztv/ztv_raster.h"

#define ZTV_MAP_MAX_PIXELS 1600u /* map pixels on the grid's long side, at most */
#define ZTV_MAP_MIN_PIXELS 1000u /* a smaller grid is enlarged to this on its long side */
#define ZTV_MAP_FLAT_GREY HILLSHADE_FLAT_GREY /* the hillshade of level ground */
#define ZTV_MAP_OPACITY 0.65     /* of the colour bands over the hillshade */

typedef struct ztv_map ztv_map;

ztv_map *ztv_map_new(const ztv_info *info, err_buf *err); /* NULL with err set */
void ztv_map_free(ztv_map *m);                            /* accepts NULL */
/* Keeps the block's cells that fall on map pixels (the caller checked the block). */
void ztv_map_block(ztv_map *m, const ztv_block *b);

/* The visible fraction of the development in mode (ztv_MODE.png). */
int ztv_map_draw_mode(const ztv_map *m, ztv_mode mode, canvas *out, err_buf *err);
/* Where the screening of mode hides what bare earth shows (ztv_hidden_MODE.png). */
int ztv_map_draw_hidden(const ztv_map *m, ztv_mode mode, canvas *out, err_buf *err);
/* Which developments are visible from each cell in mode (ztv_cumulative_MODE.png). */
int ztv_map_draw_cumulative(const ztv_map *m, ztv_mode mode, canvas *out, err_buf *err);

#endif
