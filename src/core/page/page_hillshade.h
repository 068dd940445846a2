/* page_hillshade.h — the grey of a hillshade: the ground lit by a sun in the north-west 45
 * degrees up, level ground a light grey (HILLSHADE_FLAT_GREY), slopes facing the sun lighter and
 * those turned away darker, from central differences on a grid of heights (one-sided at its edges
 * and beside cells without ground). The maps of a page (a sheet's location map, a ZTV map) share
 * it. */
#ifndef SYLVA_PAGE_HILLSHADE_H
#define SYLVA_PAGE_HILLSHADE_H

#include <stdint.h>

#define HILLSHADE_FLAT_GREY 207

/* The grey of cell (u, v) of z (w x h heights, row 0 to the north, NaN: no ground) whose cells
 * are `spacing` metres apart. */
uint8_t page_hillshade(const float *z, uint32_t w, uint32_t h, double spacing, uint32_t u, uint32_t v);

#endif
