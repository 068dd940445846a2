/* scene_file_plants.c — the plants section: each plant's species (by name), position (on the
 * terrain when no height is given, or a height above it), rotation, scale and age. */
#include "scene_file/scene_file.h"
#include "scene_file/scene_file_loader.h"

#include <math.h>

/* The plant's height above the terrain: from its map position, or its height_above_ground key
 * (a plant on a roof or a raised bed), which goes with a position of no height. */
static int read_plant_lift(loader *L, const sylva_params *p, const sf_position *pos, plant_spec *pl)
{
    const sylva_value *lift = sylva_param(p, "height_above_ground");
    pl->above_ground = isnan(pos->above_ground) ? lift->r : pos->above_ground;
    if (lift->is_set && (pos->has_height || !isnan(pos->above_ground)))
        return sf_located(L->err, L->file, lift->line, lift->column,
                          "'height_above_ground' places the plant above the terrain at [x, y]; give "
                          "'position' as [x, y] with it, or [x, y, z] without it");
    return 0;
}

/* plants: {file: F}: the plants of a saved ecology run, placed by the scene's ecology plugin. */
static int read_plants_file(loader *L, const ynode *node)
{
    param_scope scope = {L->file, L->dir, "plants", NULL, 0, node->line, node->column};
    const sylva_params *p;
    if (params_validate(L->a, node, host_schema_plants_file.params, host_schema_plants_file.n_params, &scope, &p,
                        L->err))
        return -1;
    const sylva_value *file = sylva_param(p, "file");
    scene_file *sf = L->sf;
    sf->plants_file = file->s;
    sf->plants_file_line = file->line, sf->plants_file_column = file->column;
    if (!sf->ecology.plugin)
        return sf_located(L->err, L->file, node->line, node->column,
                          "'plants: {file: ...}' places the plants of a saved ecology run, which the scene's "
                          "ecology plugin reads back; add the ecology: section the run was made with");
    return 0;
}

int sf_read_plants(loader *L, const ynode *node)
{
    if (!node || ynode_is_null(node)) return 0;
    if (node->kind == YNODE_MAPPING && ynode_get_pair(node, "file")) return read_plants_file(L, node);
    if (sf_expect_list(L, node, "plants", "- {species: name, position: [x, y]}; or {file: saved.state}, a saved "
                       "ecology run"))
        return -1;
    scene_file *sf = L->sf;
    sf->plants = arena_alloc(L->a, (size_t)node->n_items * sizeof *sf->plants + 1);
    const char **names = arena_alloc(L->a, ((size_t)sf->n_species + 1) * sizeof *names);
    if (!sf->plants || !names) return sf_out_of_memory(L);
    for (uint32_t i = 0; i < sf->n_species; i++) names[i] = sf->species[i].name;
    static const char *const position_key[] = {"position"};
    uint32_t n_keys;
    const sylva_param_spec *keys = sf_keys_without(L, &host_schema_plant, position_key, 1, &n_keys);
    if (!keys) return -1;
    for (uint32_t i = 0; i < node->n_items; i++) {
        const ynode *item = node->items[i];
        param_scope scope = {L->file, L->dir, sf_arena_printf(L->a, "plants[%u]", i), NULL, 0,
                             item->line, item->column};
        const sylva_params *p;
        if (!scope.where) return sf_out_of_memory(L);
        if (item->kind != YNODE_MAPPING)
            return sf_located(L->err, L->file, item->line, item->column,
                              "'%s' must be a mapping (species: ..., position: ...), got %s",
                              scope.where, ynode_kind_phrase(item));
        scope.host_keys = position_key, scope.n_host_keys = 1;
        sf_position pos;
        if (params_validate(L->a, item, keys, n_keys, &scope, &p, L->err) ||
            sf_read_position(L, item, sf_host_key(&host_schema_plant, "position"), scope.where, &pos))
            return -1;
        plant_spec *pl = &sf->plants[sf->n_plants];
        const sylva_value *species = sylva_param(p, "species");
        int index = scene_file_species_index(sf, species->s);
        if (index < 0)
            return sf_unknown_name(L, L->file, species, "species", "species", scope.where, names,
                                   sf->n_species);
        pl->species = (uint32_t)index;
        for (int k = 0; k < 3; k++) pl->position[k] = pos.local[k];
        pl->snap_to_terrain = !pos.has_height;
        if (read_plant_lift(L, p, &pos, pl)) return -1;
        pl->rotation_deg = sylva_param_real(p, "rotation");
        pl->scale = sylva_param_real(p, "scale");
        pl->age = sylva_param_real(p, "age");
        pl->development = (int)sylva_param(p, "development")->i;
        pl->line = item->line, pl->column = item->column;
        sf->n_plants++;
    }
    return 0;
}
