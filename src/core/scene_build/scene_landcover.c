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
