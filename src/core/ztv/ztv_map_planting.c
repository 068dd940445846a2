/* ztv_map_planting.c — the map page of what a planting plan hides at a year (ztv_map.h): the map
 * made before the plan read back from its GeoTIFF at this map's pixels (the same grid, so the same
 * cells), and each pixel drawn by what the plan changed there, with the frame, rings, viewpoints,
 * developments and title block of every visibility map. */
#include "ztv/ztv_map.h"
#include "ztv/ztv_map_style.h"

#include <math.h>
#include <stdlib.h>

#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal.h>

#include "ztv/ztv_summary.h"
#include "ztv/ztv_years.h"

/* What the planting did at a pixel: -1 no viewpoint in either map, 0 nothing seen before the
 * plan, 1 all still seen, 2 partly hidden, 3 hidden (as ztv_years.h counts the cells). */
static int planting_state(const struct ztv_map *m, const map_style *st, size_t k)
{
    if (st->before_cls[k] != ZTV_OPEN || m->cls[st->mode][k] != ZTV_OPEN) return -1;
    float before = st->before_fraction[k], now = m->fraction[st->mode][k];
    if (!(before > 0)) return 0;
    return now >= before ? 1 : now > 0 ? 2 : 3;
}

static int planting_colour(const struct ztv_map *m, const map_style *st, size_t k, uint8_t rgb[3])
{
    int cls = ztv_map_class_colour(m->cls[st->mode][k], rgb);
    if (cls) return cls;
    int state = planting_state(m, st, k);
    if (state < 0) return ztv_map_class_colour(st->before_cls[k], rgb);
    if (state == 0) return 0;
    const uint8_t *over = state == 1 ? ztv_map_still_visible_rgb
                          : state == 2 ? ztv_map_partly_hidden_rgb : ztv_map_hidden_rgb;
    for (int c = 0; c < 3; c++) rgb[c] = over[c];
    return 1;
}

/* The map before the plan at the map's pixels: band 1 (targets seen) as a share of the targets,
 * band 3 (class). */
static int read_before(const struct ztv_map *m, const char *before_dir, const char *mode_name, float *fraction,
                       uint8_t *cls, err_buf *err)
{
    char path[4200];
    ztv_years_map_path(before_dir, mode_name, path, sizeof path);
    CPLPushErrorHandler(CPLQuietErrorHandler);
    GDALDatasetH ds = GDALOpen(path, GA_ReadOnly);
    CPLPopErrorHandler();
    if (!ds) return err_fail(err, ERR_INPUT, "%s: cannot read the map made before the planting", path);
    const ztv_grid *g = &m->info->grid;
    int rc = 0;
    if ((uint32_t)GDALGetRasterXSize(ds) != g->nx || (uint32_t)GDALGetRasterYSize(ds) != g->ny)
        rc = err_fail(err, ERR_INPUT, "%s: its map is %d x %d cells, this year's %u x %u", path,
                      GDALGetRasterXSize(ds), GDALGetRasterYSize(ds), g->nx, g->ny);
    float *row = rc ? NULL : malloc(2 * (size_t)g->nx * sizeof *row); /* bands 1 and 3 of one row; freed here */
    if (!rc && !row) rc = err_nomem(err, "out of memory reading %s", path);
    for (uint32_t v = 0; !rc && v < m->h; v++) {
        int j = (int)ztv_map_sampled_cell(m, v, g->ny);
        if (GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Read, 0, j, (int)g->nx, 1, row, (int)g->nx, 1, GDT_Float32, 0,
                         0) != CE_None ||
            GDALRasterIO(GDALGetRasterBand(ds, 3), GF_Read, 0, j, (int)g->nx, 1, row + g->nx, (int)g->nx, 1,
                         GDT_Float32, 0, 0) != CE_None) {
            rc = err_fail(err, ERR_INPUT, "%s: cannot read row %d of its bands", path, j);
            break;
        }
        for (uint32_t u = 0; u < m->w; u++) {
            uint32_t i = ztv_map_sampled_cell(m, u, g->nx);
            size_t k = (size_t)v * m->w + u;
            float c = row[g->nx + i];
            cls[k] = c >= 0 && c < ZTV_CLASSES ? (uint8_t)c : ZTV_OUTSIDE;
            fraction[k] = m->info->n_targets ? row[i] / (float)m->info->n_targets : 0;
        }
    }
    free(row);
    GDALClose(ds);
    return rc;
}

int ztv_map_write_planting(const ztv_map *m, ztv_mode mode, FILE *png, FILE *pdf, err_buf *err)
{
    const char *before_dir = m->info->planting_before;
    double year = m->info->planting_year;
    if (!before_dir) return err_fail(err, ERR_INTERNAL, "no map made before the planting to compare with");
    if (mode >= ZTV_MODES || !m->cls[mode])
        return err_fail(err, ERR_INTERNAL, "the visibility map has no %s results to draw", ztv_mode_name(mode));
    size_t n = (size_t)m->w * m->h;
    float *fraction = malloc(n * sizeof *fraction); /* freed here */
    uint8_t *cls = malloc(n);                       /* freed here */
    int rc = fraction && cls ? 0 : err_nomem(err, "out of memory for the map made before the planting");
    if (!rc) rc = read_before(m, before_dir, ztv_mode_name(mode), fraction, cls, err);
    if (!rc) {
        map_style st = {.mode = mode, .colour = planting_colour, .before_fraction = fraction, .before_cls = cls};
        snprintf(st.title, sizeof st.title, "hidden by the planting, %g year%s after planting", year,
                 year == 1 ? "" : "s");
        snprintf(st.legend_title, sizeof st.legend_title, "the development seen before the plan against year %g",
                 year);
        const char *labels[4] = {"hidden by the planting", "partly hidden by the planting", "seen as before the plan",
                                 "not seen before the plan"};
        ztv_map_add_hidden_items(m, &st, labels);
        rc = ztv_map_page(m, &st, png, pdf, err);
    }
    free(fraction);
    free(cls);
    return rc;
}
