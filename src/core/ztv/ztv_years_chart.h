/* ztv_years_chart.h — the chart of a planting plan's visibility over the years
 * (visible_area.png of `sylva ztv --years`, docs/mitigation.md): drawn on a page (page/page.h)
 * with the sheets' and maps' typeface, two panels side by side over the years since planting,
 * each with its axis from zero: the area from which the development is seen (km²), with the area
 * before the plan for reference and the change written out; and the area where the planting
 * hides it (hectares), wholly and in part. */
#ifndef SYLVA_ZTV_YEARS_CHART_H
#define SYLVA_ZTV_YEARS_CHART_H

#include <stdint.h>

#include "util/err.h"

/* The areas of each year since planting (n years, increasing), km2, and the visible area before
 * the plan. Nothing is owned. */
typedef struct ztv_years_areas {
    const double *year, *visible_km2, *hidden_km2, *partly_km2;
    uint32_t n;
    double before_km2;
} ztv_years_areas;

/* Writes the chart of a (1 to 255 years) as png_path. Returns 0, or -1 with err set and nothing
 * written. */
int ztv_years_chart_write(const char *png_path, const ztv_years_areas *a, err_buf *err);

#endif
