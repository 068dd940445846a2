/* ztv_years.h — a planting plan's visibility over the years (`sylva ztv --years`, docs/mitigation.md):
 * from the maps made before the plan and at each year after planting (each a `sylva ztv` output
 * folder, screened by the plants), the map of what the planting hides in each year and the table
 * and chart of the area from which the development is seen against the years since planting.
 *
 * Files: in each year's folder ztv_hidden_by_planting.tif (GeoTIFF, Float32: band 1 the targets
 * seen before the plan and not that year, band 2 the cell's class that year; nodata -1 where the
 * cell is no viewpoint in either); in the parent folder visible_area.csv and visible_area.png. The
 * year's run draws the map page of the same comparison, ztv_hidden_by_planting.png and .pdf
 * (ztv_map_write_planting, ztv_map.h), as it draws its other maps. */
#ifndef SYLVA_ZTV_YEARS_H
#define SYLVA_ZTV_YEARS_H

#include <stddef.h>
#include <stdint.h>

#include "util/err.h"

typedef struct ztv_year_row {
    double year;          /* years since planting; < 0 for the map before the plan */
    const char *dir;      /* its ztv output folder */
    double visible_km2;   /* area from which some target is seen (filled by ztv_years_write) */
    double hidden_km2;    /* area from which the plan hides every target seen before it (likewise) */
    double partly_km2;    /* area from which it hides some of them (likewise) */
} ztv_year_row;

/* rows[0] is the map before the plan; rows[1..n) the years, increasing. mode is the screened
 * mode's name ("vegetation", "all"). Writes the per-year maps and dir's table and chart.
 * Returns 0, or -1 with err set. */
int ztv_years_write(const char *dir, const char *mode, ztv_year_row *rows, uint32_t n, err_buf *err);

/* The path of the map of mode in output folder dir (the mode it fell back to when a scene with
 * less in it had no such map: all without objects is vegetation, without plants bare earth). */
void ztv_years_map_path(const char *dir, const char *mode, char *path, size_t n);

/* The area in km2 from which some target is seen in mode, from a ztv_summary.csv. Returns 0, or -1
 * with err set. */
int ztv_years_visible_area(const char *summary_csv, const char *mode, double *km2, err_buf *err);

#endif
