/* ztv_summary.h — the areas of a visibility map, counted as the blocks of rows arrive and
 * written as ztv_summary.csv and ztv_summary.json (docs/ztv.md, "Outputs"): per mode the area
 * from which each band of the development's visible fraction is seen, the areas under crowns,
 * inside objects and not computed, per development the area from which it is seen, and per
 * screened mode the area its screening hides. Only counts are kept: memory does not grow with
 * the grid.
 *
 * Ownership: ztv_summary_new returns a summary that ztv_summary_free releases; it keeps info
 * (which must outlive it). */
#ifndef SYLVA_ZTV_SUMMARY_H
#define SYLVA_ZTV_SUMMARY_H

#include <stdint.h>
#include <stdio.h>

#include "util/err.h"
#include "ztv/ztv_raster.h"

/* The bands of the visible fraction f of an open cell, as the maps colour them and the summary
 * counts them. */
typedef enum ztv_band {
    ZTV_BAND_NONE = 0, /* f = 0 */
    ZTV_BAND_1_25,     /* 0 < f <= 0.25 */
    ZTV_BAND_25_50,    /* 0.25 < f <= 0.5 */
    ZTV_BAND_50_75,    /* 0.5 < f <= 0.75 */
    ZTV_BAND_75_100,   /* 0.75 < f < 1 */
    ZTV_BAND_ALL,      /* f = 1 */
    ZTV_BANDS
} ztv_band;

ztv_band ztv_band_of(float fraction);
/* "0", "1-25", "25-50", "50-75", "75-<100", "100" (percent). */
const char *ztv_band_label(ztv_band band);
/* "bare", "vegetation", "all", "canopy": the name in file names and summaries. */
const char *ztv_mode_name(ztv_mode mode);

typedef struct ztv_summary ztv_summary;

ztv_summary *ztv_summary_new(const ztv_info *info, err_buf *err); /* NULL with err set */
void ztv_summary_free(ztv_summary *s);                            /* accepts NULL */
/* Counts a block's cells (checked by the caller: every computed mode's layer present). */
void ztv_summary_block(ztv_summary *s, const ztv_block *b);
/* The summary as a table (one quantity a row) and as a JSON object; 0, or -1 with err set
 * when the stream fails. */
int ztv_summary_write_csv(const ztv_summary *s, FILE *f, err_buf *err);
int ztv_summary_write_json(const ztv_summary *s, FILE *f, err_buf *err);

#endif
