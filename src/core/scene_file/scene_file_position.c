/* scene_file_position.c — every position a scene file gives (camera position and look_at, plant
 * positions, the inline grid's origin, object positions): a list of local metres, or a mapping
 * in map coordinates (easting/northing or longitude/latitude through the site's CRS) with a
 * height or a height above ground. Map coordinates become local ones at once, in double
 * precision: local = map - site origin. Heights above ground stay as such until the terrain
 * exists (scene_build.c). */
#include "scene_file/scene_file_loader.h"

#include <math.h>
#include <string.h>

const sylva_param_spec *sf_keys_without(loader *L, const host_schema *schema, const char *const *drop,
                                        uint32_t n_drop, uint32_t *n_out)
{
    sylva_param_spec *keys = arena_alloc(L->a, ((size_t)schema->n_params + 1) * sizeof *keys);
    if (!keys) {
        sf_out_of_memory(L);
        return NULL;
    }
    uint32_t n = 0;
    for (uint32_t i = 0; i < schema->n_params; i++) {
        uint32_t k = 0;
        while (k < n_drop && strcmp(drop[k], schema->params[i].name)) k++;
        if (k == n_drop) keys[n++] = schema->params[i];
    }
    *n_out = n;
    return keys;
}

/* Of two keys that exclude each other, the one given later in the file. */
static const sylva_value *later(const sylva_value *a, const sylva_value *b)
{
    if (a->line != b->line) return a->line > b->line ? a : b;
    return a->column > b->column ? a : b;
}

/* A mapping {easting, northing | longitude, latitude, height | height_above_ground}. */
static int read_map_position(loader *L, const ynode *node, const sylva_param_spec *spec,
                             const char *where, sf_position *out)
{
    const char *key = spec->name;
    const char *block = sf_arena_printf(L->a, "%s.%s", where, key);
    if (!block) return sf_out_of_memory(L);
    param_scope scope = {L->file, L->dir, block, NULL, 0, node->line, node->column};
    const sylva_params *p;
    if (params_validate(L->a, node, host_schema_position.params, host_schema_position.n_params, &scope,
                        &p, L->err))
        return -1;
    const sylva_value *e = sylva_param(p, "easting"), *n = sylva_param(p, "northing"),
                      *lon = sylva_param(p, "longitude"), *lat = sylva_param(p, "latitude"),
                      *h = sylva_param(p, "height"), *hag = sylva_param(p, "height_above_ground");
    int flat = spec->max_len == 2;
    if (!L->site)
        return sf_located(L->err, L->file, node->line, node->column,
                          "'%s' is given in map coordinates, but the scene has no 'site:' section "
                          "to say in which CRS; add site: {crs: EPSG:NNNN, origin: [E, N]}, or give "
                          "[x, y%s] in local metres", block, flat ? "" : ", z");
    if ((e->is_set || n->is_set) && (lon->is_set || lat->is_set)) {
        const sylva_value *at = later(e->is_set ? e : n, lon->is_set ? lon : lat);
        return sf_located(L->err, L->file, at->line, at->column,
                          "'%s' takes easting/northing or longitude/latitude, not both", block);
    }
    if (e->is_set != n->is_set || lon->is_set != lat->is_set || !(e->is_set || lon->is_set)) {
        const char *missing = e->is_set ? "northing" : n->is_set ? "easting"
                            : lon->is_set ? "latitude" : lat->is_set ? "longitude" : NULL;
        if (missing)
            return sf_located(L->err, L->file, node->line, node->column, "'%s' lacks '%s'", block,
                              missing);
        return sf_located(L->err, L->file, node->line, node->column,
                          "'%s' needs easting and northing, or longitude and latitude", block);
    }
    if (h->is_set && hag->is_set) {
        const sylva_value *at = later(h, hag);
        return sf_located(L->err, L->file, at->line, at->column,
                          "'%s' takes 'height' or 'height_above_ground', not both", block);
    }
    if (flat && (h->is_set || hag->is_set)) {
        const sylva_value *at = h->is_set ? h : hag;
        return sf_located(L->err, L->file, at->line, at->column,
                          "'%s' is a point on the map and takes no height; remove it", block);
    }
    double map[2] = {e->r, n->r};
    if (lon->is_set) {
        err_buf why = {{0}};
        if (site_frame_from_lonlat(L->site, lon->r, lat->r, map, &why))
            return sf_located(L->err, L->file, lon->line, lon->column, "'%s': %s", block, why.msg);
    }
    const double *origin = L->sf->site.origin;
    out->local[0] = map[0] - origin[0];
    out->local[1] = map[1] - origin[1];
    out->has_height = h->is_set;
    out->local[2] = h->is_set ? h->r - origin[2] : 0.0;
    out->above_ground = hag->is_set ? hag->r : NAN;
    return 0;
}

int sf_read_position(loader *L, const ynode *map, const sylva_param_spec *spec, const char *where,
                     sf_position *out)
{
    const ynode_pair *pr = ynode_get_pair(map, spec->name);
    const ynode *node = pr ? pr->value : NULL;
    *out = (sf_position){.above_ground = NAN, .line = map->line, .column = map->column};
    if (!node) {
        if (spec->flags & SYLVA_PARAM_REQUIRED)
            return sf_located(L->err, L->file, map->line, map->column, "missing required key '%s' in '%s'",
                              spec->name, where);
        for (uint32_t k = 0; k < spec->def_len && k < 3; k++) out->local[k] = spec->def_list[k];
        out->has_height = spec->def_len == 3;
        return 0;
    }
    out->given = 1;
    out->line = node->line, out->column = node->column;
    if (node->kind == YNODE_MAPPING) return read_map_position(L, node, spec, where, out);
    if (node->kind != YNODE_SEQUENCE) {
        int flat = spec->max_len == 2;
        return sf_located(L->err, L->file, node->line, node->column,
                          "'%s' must be %s in local metres, or a mapping in map coordinates "
                          "{easting: E, northing: N%s}, got %s", spec->name,
                          flat                                                ? "[x, y]"
                          : spec->type == SYLVA_P_VEC3 || spec->min_len == 3 ? "[x, y, z]"
                                                                              : "[x, y, z] or [x, y]",
                          flat ? "" : ", height: h", ynode_kind_phrase(node));
    }
    param_scope scope = {L->file, L->dir, where, NULL, 0, node->line, node->column};
    sylva_value v;
    if (param_value_read(L->a, node, spec, &scope, &v, L->err)) return -1;
    for (uint32_t k = 0; k < v.len && k < 3; k++) out->local[k] = v.list[k];
    out->has_height = v.len == 3;
    return 0;
}
