/* scene_file_species.c — each gathered species: a tree plugin and its parameters, or a
 * built-in shape and its material; the number of age variants; and its block under the ecology
 * plugin's species section (the plugin's defaults when the block is left out). */
#include "scene_file/scene_file_loader.h"

#include <string.h>

static int read_species_entry(loader *L, const species_entry *e, species_spec *sp)
{
    const char *file = e->file;
    param_scope scope = {file, e->dir, sf_arena_printf(L->a, "species.%s", e->name), NULL, 0,
                         e->line, e->column};
    if (!scope.where) return sf_out_of_memory(L);
    const ynode *map = e->node;
    if (map->kind != YNODE_MAPPING)
        return sf_located(L->err, file, map->line, map->column,
                          "species '%s' must be a mapping (plugin: ... or shape: ...), got %s",
                          e->name, ynode_kind_phrase(map));
    sp->name = e->name;
    sp->line = e->line, sp->column = e->column;
    const ynode_pair *pp = ynode_get_pair(map, "plugin"), *shp = ynode_get_pair(map, "shape");
    if (pp && shp)
        return sf_located(L->err, file, shp->key_line, shp->key_column,
                          "species '%s' gives both 'plugin' and 'shape'; give one of them", e->name);
    if (!pp && !shp)
        return sf_located(L->err, file, map->line, map->column,
                          "species '%s' needs 'plugin' (a tree plugin) or 'shape' (mesh, box, "
                          "sphere, quad or disk)", e->name);
    const sylva_params *host;
    const sylva_param_spec *hs = host_schema_species.params;
    uint32_t hn = host_schema_species.n_params;
    const char *section = L->species_section;
    if (pp) {
        const sylva_plugin *d;
        if (sf_find_plugin(L, &scope, pp, sf_host_key(&host_schema_species, "plugin"), SYLVA_KIND_TREE,
                           &d, &sp->plugin))
            return -1;
        if (sf_validate_shared(L, map, &scope, hs, hn, d->params, d->n_params, section, &host,
                               &sp->params))
            return -1;
        const sylva_value *mat = sylva_param(host, "material");
        if (mat->is_set)
            return sf_located(L->err, file, mat->line, mat->column,
                              "'material' applies to built-in shapes; tree plugin '%s' makes its "
                              "own materials", sp->plugin);
        sp->variants = (uint32_t)sylva_param_int(host, "variants");
    } else {
        sylva_value kind;
        if (param_value_read(L->a, shp->value, sf_host_key(&host_schema_species, "shape"), &scope,
                             &kind, L->err))
            return -1;
        const host_schema *shape = host_schema_shape((shape_kind)kind.i);
        const sylva_params *shape_params;
        if (sf_validate_shared(L, map, &scope, hs, hn, shape->params, shape->n_params, section,
                               &host, &shape_params))
            return -1;
        const sylva_value *variants = sylva_param(host, "variants");
        if (variants->is_set)
            return sf_located(L->err, file, variants->line, variants->column,
                              "'variants' applies to plugin species; a built-in shape has one form");
        if (sf_read_shape(L, file, (shape_kind)kind.i, shape_params, map, &sp->shape)) return -1;
        if (sf_material_ref(L, file, sylva_param(host, "material"), scope.where, &sp->material))
            return -1;
        sp->variants = 1;
    }
    if (sf_read_phenology(L, file, e->name, sylva_param(host, "phenology"), &sp->phenology)) return -1;
    const ynode_pair *eco = ynode_get_pair(map, section);
    if (!eco) {
        /* A species without a block takes the ecology plugin's defaults, so the plugin always
         * receives a complete block for every species. */
        if (!L->ecology || !L->ecology->species_section) return 0;
        param_scope ds = {file, e->dir, sf_arena_printf(L->a, "species.%s.%s", e->name, section), NULL, 0,
                          e->line, e->column};
        if (!ds.where) return sf_out_of_memory(L);
        return params_validate(L->a, NULL, L->ecology->species_params, L->ecology->n_species_params,
                               &ds, &sp->ecology, L->err);
    }
    /* A library of species carries the ecology blocks that a scene growing them needs; a scene
     * without an ecology places its plants by other means and leaves an included file's blocks
     * unread. A block in the scene file itself is a mistake there. */
    if (!L->ecology && strcmp(file, L->file) != 0) return 0;
    if (!L->ecology)
        return sf_located(L->err, file, eco->key_line, eco->key_column,
                          "species '%s' has an '%s:' block, but the scene has no 'ecology:' section "
                          "to use it; add one (ecology: {plugin: ...}) or remove this block",
                          e->name, section);
    if (!L->ecology->species_section)
        return sf_located(L->err, file, eco->key_line, eco->key_column,
                          "ecology plugin '%s' takes no per-species block; remove '%s:' from "
                          "species '%s'", L->sf->ecology.plugin, section, e->name);
    param_scope es = {file, e->dir, sf_arena_printf(L->a, "species.%s.%s", e->name, section), NULL, 0,
                      eco->key_line, eco->key_column};
    if (!es.where) return sf_out_of_memory(L);
    return params_validate(L->a, eco->value, L->ecology->species_params,
                           L->ecology->n_species_params, &es, &sp->ecology, L->err);
}

int sf_read_species(loader *L, const ynode *node)
{
    if (!node) return 0;
    if (sf_collect_species(L, node, L->file, L->dir)) return -1;
    scene_file *sf = L->sf;
    sf->species = arena_alloc(L->a, (size_t)L->n_entries * sizeof *sf->species + 1);
    if (!sf->species) return sf_out_of_memory(L);
    for (uint32_t i = 0; i < L->n_entries; i++) {
        if (read_species_entry(L, &L->entries[i], &sf->species[i])) return -1;
        sf->n_species = i + 1;
    }
    return 0;
}
