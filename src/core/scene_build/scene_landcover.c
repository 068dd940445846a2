/* scene_landcover.c — the land-cover map onto the ground as surveyed (scene_landcover.h). */
#include "scene_build/scene_landcover.h"

#include <stdio.h>

#include "site/landcover.h"

int scene_build_landcover(scene *s, const scene_file *sf, int quiet, err_buf *err)
{
    const landcover_spec *spec = &sf->landcover;
    if (!spec->given) return 0;
    const sylva_heightfield *hf = s->surveyed;
    if (!hf)
        return err_at(err, ERR_INPUT, sf->path, spec->line, spec->column,
                      "the land-cover map is read onto the site's ground, but the scene has no terrain; add a "
                      "terrain: section (a DTM, or a grid)");
    landcover_grid grid = {sf->site.crs_wkt, {sf->site.origin[0], sf->site.origin[1]}, hf->nx, hf->ny,
                           hf->x0, hf->y0, hf->dx, hf->dy};
    land_cover *lc = landcover_read(&spec->source, &grid, stderr, quiet ? NULL : stderr, err);
    if (!lc) {
        err_default(err, ERR_INPUT);
        return err->status == ERR_NOMEM ? -1 : err_locate(err, sf->path, spec->line, spec->column);
    }
    s->land_cover = lc;
    return 0;
}

#define SHARES_HALF_SIDE 5000.0 /* metres from the site origin */
#define SHARES_SPACING 100.0

/* The cover kind a land kind counts toward; -1: none (unknown). */
static int cover_kind(land_kind k)
{
    switch (land_kind_broad(k)) {
    case LAND_FOREST: return SYLVA_COVER_FOREST;
    case LAND_SHRUB: return SYLVA_COVER_SHRUB;
    case LAND_GRASS: return SYLVA_COVER_GRASS;
    case LAND_CULTIVATED: return SYLVA_COVER_CULTIVATED;
    case LAND_BARREN: return SYLVA_COVER_BARREN;
    case LAND_SNOW_ICE: return SYLVA_COVER_SNOW;
    case LAND_WATER: return SYLVA_COVER_WATER;
    case LAND_DEVELOPED: return SYLVA_COVER_DEVELOPED;
    case LAND_WETLAND: return SYLVA_COVER_WETLAND;
    default: return -1;
    }
}

int scene_landcover_shares(const scene_file *sf, double shares[SYLVA_COVER_KINDS])
{
    if (!sf->landcover.given || !sf->site.crs_wkt) return 0;
    uint32_t n = (uint32_t)(2 * SHARES_HALF_SIDE / SHARES_SPACING) + 1;
    landcover_grid grid = {sf->site.crs_wkt, {sf->site.origin[0], sf->site.origin[1]}, n, n,
                           -SHARES_HALF_SIDE, -SHARES_HALF_SIDE, SHARES_SPACING, SHARES_SPACING};
    err_buf err = {{0}};
    land_cover *lc = landcover_read(&sf->landcover.source, &grid, NULL, NULL, &err); /* owned here */
    if (!lc) return 0;
    double count[SYLVA_COVER_KINDS] = {0}, total = 0;
    for (uint32_t c = 0; c < lc->n_classes; c++) {
        int k = cover_kind(lc->classes[c].kind);
        if (k >= 0) count[k] += (double)lc->classes[c].nodes;
        total += (double)lc->classes[c].nodes;
    }
    land_cover_free(lc);
    if (!(total > 0)) return 0;
    for (int k = 0; k < SYLVA_COVER_KINDS; k++) shares[k] = count[k] / total;
    return 1;
}
