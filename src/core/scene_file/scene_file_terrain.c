/* scene_file_terrain.c — the terrain section: inline heights (grid, origin, spacing) or a
 * terrain plugin and its parameters, never both, and the ground material. */
#include "scene_file/scene_file_loader.h"

int sf_read_terrain(loader *L, const ynode *node, uint32_t line, uint32_t column)
{
    terrain_spec *t = &L->sf->terrain;
    if (!node || ynode_is_null(node)) return 0;
    param_scope scope = {L->file, L->dir, "terrain", NULL, 0, line, column};
    const sylva_params *host;
    if (node->kind != YNODE_MAPPING)
        return sf_located(L->err, L->file, node->line, node->column,
                          "'terrain' must be a mapping (grid: ... or plugin: ...), got %s",
                          ynode_kind_phrase(node));
    t->line = node->line, t->column = node->column;
    static const char *const origin_key[] = {"origin"};
    uint32_t n_keys;
    const sylva_param_spec *keys = sf_keys_without(L, &host_schema_terrain, origin_key, 1, &n_keys);
    if (!keys) return -1;
    sf_position origin;
    const ynode_pair *pp = ynode_get_pair(node, "plugin");
    if (pp) {
        const sylva_plugin *d;
        if (sf_find_plugin(L, &scope, pp, sf_host_key(&host_schema_terrain, "plugin"), SYLVA_KIND_TERRAIN,
                           &d, &t->plugin))
            return -1;
        if (sf_validate_shared(L, node, &scope, keys, n_keys, d->params, d->n_params, "origin", &host,
                               &t->params))
            return -1;
        static const char *const inline_keys[] = {"grid", "origin", "spacing"};
        for (int k = 0; k < 3; k++) {
            const ynode *v = ynode_get(node, inline_keys[k]);
            if (v)
                return sf_located(L->err, L->file, v->line, v->column,
                                  "'%s' belongs to an inline terrain; with plugin: the plugin '%s' "
                                  "builds the heights (remove '%s' or 'plugin')",
                                  inline_keys[k], t->plugin, inline_keys[k]);
        }
        t->source = TERRAIN_PLUGIN;
    } else {
        scope.host_keys = origin_key, scope.n_host_keys = 1;
        if (params_validate(L->a, node, keys, n_keys, &scope, &host, L->err) ||
            sf_read_position(L, node, sf_host_key(&host_schema_terrain, "origin"), "terrain", &origin))
            return -1;
        const sylva_value *grid = sylva_param(host, "grid");
        if (!grid->is_set)
            return sf_located(L->err, L->file, node->line, node->column,
                              "'terrain' needs either 'grid' (inline heights) or 'plugin' (a "
                              "terrain plugin)");
        if (grid->rows < 2 || grid->cols < 2)
            return sf_located(L->err, L->file, grid->line, grid->column,
                              "'grid' needs at least 2 rows and 2 columns of heights, got %u x %u",
                              grid->rows, grid->cols);
        const sylva_value *spacing = sylva_param(host, "spacing");
        t->source = TERRAIN_GRID;
        t->grid = grid->list, t->nx = grid->cols, t->ny = grid->rows;
        t->origin[0] = origin.local[0], t->origin[1] = origin.local[1];
        t->spacing[0] = spacing->list[0], t->spacing[1] = spacing->list[1];
    }
    return sf_material_ref(L, L->file, sylva_param(host, "material"), "terrain", &t->material);
}
