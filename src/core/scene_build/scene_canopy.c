/* scene_canopy.c — the canopy heights onto the ground as surveyed (scene_canopy.h). */
#include "scene_build/scene_canopy.h"

#include <stdio.h>

#include "site/canopy_read.h"

int scene_build_canopy(scene *s, const scene_file *sf, int quiet, err_buf *err)
{
    const canopy_spec *spec = &sf->canopy;
    if (!spec->given) return 0;
    const sylva_heightfield *hf = s->surveyed;
    if (!hf)
        return err_at(err, ERR_INPUT, sf->path, spec->line, spec->column,
                      "the canopy's heights are read onto the site's ground, but the scene has no terrain; add a "
                      "terrain: section (a DTM, or a grid)");
    landcover_grid grid = {sf->site.crs_wkt, {sf->site.origin[0], sf->site.origin[1]}, hf->nx, hf->ny,
                           hf->x0, hf->y0, hf->dx, hf->dy};
    canopy_fault fault;
    canopy *c = canopy_read(&spec->source, &grid, stderr, quiet ? NULL : stderr, &fault, err);
    if (!c) {
        err_default(err, ERR_INPUT);
        if (err->status == ERR_NOMEM) return -1;
        return fault == CANOPY_FAULT_DTM ? err_locate(err, sf->path, spec->dtm_line, spec->dtm_column)
                                         : err_locate(err, sf->path, spec->line, spec->column);
    }
    s->canopy = c;
    return 0;
}
