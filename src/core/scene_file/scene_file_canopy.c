/* scene_file_canopy.c — the canopy: section: the site's canopy heights, from a canopy height
 * model (chm:) or a surface model less its terrain model (dsm: with dtm:). The files are opened
 * here to check what can be checked before the site's grid exists (readable rasters,
 * georeferenced, with a CRS), each fault placed at its key; they are read onto the grid when the
 * scene is built (scene_build/scene_canopy.c). */
#include "scene_file/scene_file_loader.h"

#include "util/file_check.h"

static const char canopy_forms[] = "chm: FILE (heights above the ground) or dsm: FILE with dtm: FILE (a surface "
                                   "model and the terrain model under it)";

/* Exactly chm, or dsm with dtm: each other combination refused at the key that breaks it. */
static int heights_keys(loader *L, const ynode_pair *pr, const sylva_value *chm, const sylva_value *dsm,
                        const sylva_value *dtm)
{
    const sylva_value *extra = chm->is_set ? (dsm->is_set ? dsm : dtm->is_set ? dtm : NULL) : NULL;
    if (extra)
        return sf_located(L->err, L->file, extra->line, extra->column, "'canopy' gives both 'chm' and '%s'; give "
                          "one source of heights: %s", extra == dsm ? "dsm" : "dtm", canopy_forms);
    if (dsm->is_set && !dtm->is_set)
        return sf_located(L->err, L->file, dsm->line, dsm->column, "'dsm' needs dtm: FILE, the terrain model "
                          "under it: the canopy's heights are the surface model less the terrain model");
    if (dtm->is_set && !dsm->is_set)
        return sf_located(L->err, L->file, dtm->line, dtm->column, "'dtm' is the terrain model under a surface "
                          "model; give dsm: FILE beside it, or chm: FILE alone");
    if (!chm->is_set && !dsm->is_set)
        return sf_located(L->err, L->file, pr->key_line, pr->key_column, "'canopy' names no heights; give %s",
                          canopy_forms);
    return 0;
}

/* Each file: a regular local file (a GDAL virtual path only when the command line allowed it),
 * a georeferenced raster with a CRS. */
static int check_files(loader *L, const canopy_source *src, const sylva_value *first, const sylva_value *dtm)
{
    err_buf why = {{0}};
    const char *paths[2] = {src->chm ? src->chm : src->dsm, src->dtm};
    const sylva_value *keys[2] = {first, dtm};
    for (int k = 0; k < (src->chm ? 1 : 2); k++)
        if (!file_is_gdal_virtual(paths[k]) && file_check_regular(paths[k], NULL, &why))
            return sf_located(L->err, L->file, keys[k]->line, keys[k]->column, "the canopy's '%s': %s; name a "
                              "raster file", k ? "dtm" : src->chm ? "chm" : "dsm", why.msg);
    canopy_fault fault;
    if (!canopy_check(src, &fault, &why)) return 0;
    const sylva_value *at = fault == CANOPY_FAULT_DTM ? dtm : first;
    return sf_located(L->err, L->file, at->line, at->column, "%s", why.msg);
}

int sf_read_canopy(loader *L)
{
    const ynode_pair *pr = ynode_get_pair(L->root, "canopy");
    if (!pr) return 0;
    param_scope scope = {L->file, L->dir, "canopy", NULL, 0, pr->key_line, pr->key_column};
    const sylva_params *p;
    if (params_validate(L->a, pr->value, host_schema_canopy.params, host_schema_canopy.n_params, &scope, &p, L->err))
        return -1;
    if (!L->sf->site.crs_wkt)
        return sf_located(L->err, L->file, pr->key_line, pr->key_column,
                          "'canopy' puts heights on the site, but the scene has no 'site:' section; add site: {} "
                          "(the CRS and origin from the DTM) or site: {crs: ..., origin: ...}");
    const sylva_value *chm = sylva_param(p, "chm"), *dsm = sylva_param(p, "dsm"), *dtm = sylva_param(p, "dtm");
    if (heights_keys(L, pr, chm, dsm, dtm)) return -1;
    canopy_spec *c = &L->sf->canopy;
    const sylva_value *first = chm->is_set ? chm : dsm;
    c->source = (canopy_source){chm->is_set ? chm->s : NULL, dsm->is_set ? dsm->s : NULL, dtm->is_set ? dtm->s : NULL};
    c->line = first->line, c->column = first->column;
    c->dtm_line = dtm->line, c->dtm_column = dtm->column;
    c->fit_plants = (int)sylva_param(p, "fit_plants")->i;
    if (check_files(L, &c->source, first, dtm)) return -1;
    c->given = 1;
    return 0;
}
