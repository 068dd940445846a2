/* scene_file_landcover.c — the landcover: section: the site's land-cover map (a raster, or
 * polygons with their class field), its legend and the classes the scene names. The map is
 * opened here to check what can be checked before the site's grid exists (a readable file,
 * georeferenced, the layer and the class field), each fault placed at its key; it is read onto
 * the grid when the scene is built (scene_build/scene_landcover.c). */
#include "scene_file/scene_file_loader.h"

#include "site/landcover.h"
#include "util/file_check.h"

/* The key that says where the map is: exactly one of raster and polygons. */
static int map_key(loader *L, const ynode_pair *pr, const sylva_params *p, const sylva_value **map)
{
    const sylva_value *raster = sylva_param(p, "raster"), *polygons = sylva_param(p, "polygons");
    if (raster->is_set && polygons->is_set)
        return sf_located(L->err, L->file, polygons->line, polygons->column,
                          "'landcover' gives both 'raster' and 'polygons'; give one map: raster: FILE (a "
                          "classified raster) or polygons: FILE with class_field: NAME");
    if (!raster->is_set && !polygons->is_set)
        return sf_located(L->err, L->file, pr->key_line, pr->key_column,
                          "'landcover' names no map; give raster: FILE (a classified raster) or polygons: "
                          "FILE with class_field: NAME");
    *map = raster->is_set ? raster : polygons;
    return 0;
}

/* The keys only polygons read, checked against the form. */
static int polygon_keys(loader *L, const sylva_params *p, const sylva_value *map, landcover_source *src)
{
    const sylva_value *layer = sylva_param(p, "layer"), *field = sylva_param(p, "class_field");
    if (src->form == LANDCOVER_RASTER) {
        const sylva_value *v = layer->is_set ? layer : field->is_set ? field : NULL;
        if (v)
            return sf_located(L->err, L->file, v->line, v->column, "'%s' is for polygons; a raster's cells "
                              "hold the class codes themselves", layer->is_set ? "layer" : "class_field");
        return 0;
    }
    if (!field->is_set)
        return sf_located(L->err, L->file, map->line, map->column, "'polygons' needs class_field: NAME, the "
                          "attribute that holds each polygon's class (a code or a class name)");
    src->layer = layer->is_set ? layer->s : NULL;
    src->class_field = field->s;
    return 0;
}

/* The classes: list into the source (in the arena); a code given twice is refused. */
static int read_classes(loader *L, const sylva_value *v, landcover_source *src)
{
    if (!v->len) return 0;
    landcover_class_spec *cs = arena_alloc(L->a, v->len * sizeof *cs);
    if (!cs) return sf_out_of_memory(L);
    for (uint32_t i = 0; i < v->len; i++) {
        const sylva_params *item = &v->items[i];
        const sylva_value *code = sylva_param(item, "code"), *name = sylva_param(item, "name");
        const sylva_value *kind = sylva_param(item, "kind");
        for (uint32_t k = 0; k < i; k++)
            if (cs[k].code == code->i)
                return sf_located(L->err, L->file, code->line, code->column, "class %lld is given twice in "
                                  "'classes'; give each code once", (long long)code->i);
        cs[i] = (landcover_class_spec){code->i, name->is_set ? name->s : NULL, kind->is_set ? (int)kind->i : -1};
    }
    src->classes = cs, src->n_classes = v->len;
    return 0;
}

/* The map's file: a regular local file (a GDAL virtual path only when the command line allowed
 * it, which the validation checked), readable as the form says, with its layer and field. */
static int check_map(loader *L, const sylva_params *p, const sylva_value *map, const landcover_source *src)
{
    err_buf why = {{0}};
    if (!file_is_gdal_virtual(src->path) && file_check_regular(src->path, NULL, &why))
        return sf_located(L->err, L->file, map->line, map->column, "the land-cover map: %s; name a %s file",
                          why.msg, src->form == LANDCOVER_RASTER ? "raster" : "vector");
    landcover_fault fault;
    if (!landcover_check(src, &fault, &why)) return 0;
    const sylva_value *at = fault == LANDCOVER_FAULT_LAYER ? sylva_param(p, "layer")
                          : fault == LANDCOVER_FAULT_FIELD ? sylva_param(p, "class_field") : map;
    return sf_located(L->err, L->file, at->line, at->column, "%s", why.msg);
}

int sf_read_landcover(loader *L)
{
    const ynode_pair *pr = ynode_get_pair(L->root, "landcover");
    if (!pr) return 0;
    param_scope scope = {L->file, L->dir, "landcover", NULL, 0, pr->key_line, pr->key_column};
    const sylva_params *p;
    if (params_validate(L->a, pr->value, host_schema_landcover.params, host_schema_landcover.n_params, &scope, &p,
                        L->err))
        return -1;
    if (!L->sf->site.crs_wkt)
        return sf_located(L->err, L->file, pr->key_line, pr->key_column,
                          "'landcover' puts a map on the site, but the scene has no 'site:' section; add "
                          "site: {} (the CRS and origin from the DTM) or site: {crs: ..., origin: ...}");
    const sylva_value *map = NULL;
    if (map_key(L, pr, p, &map)) return -1;
    landcover_spec *lc = &L->sf->landcover;
    landcover_source *src = &lc->source;
    src->form = map == sylva_param(p, "raster") ? LANDCOVER_RASTER : LANDCOVER_POLYGONS;
    src->path = map->s;
    src->legend = (landcover_legend)sylva_param(p, "legend")->i;
    lc->line = map->line, lc->column = map->column;
    if (polygon_keys(L, p, map, src) || read_classes(L, sylva_param(p, "classes"), src) ||
        check_map(L, p, map, src) || sf_read_communities(L, p, lc))
        return -1;
    lc->given = 1;
    return 0;
}
