/* scene_file_plants.c — the plants section: each plant's species (by name), position (on the
 * terrain when z is left out, or a height above it), rotation, scale and age. */
#include "scene/scene_file_loader.h"

/* height_above_ground: the base stands that far above the terrain at [x, y] (a plant on a roof
 * or a raised bed); with a z of its own the plant is placed already. */
static int read_plant_lift(loader *L, const sylva_params *p, plant_spec *pl)
{
    const sylva_value *lift = sylva_param(p, "height_above_ground");
    pl->height_above_ground = lift->r;
    if (lift->is_set && !pl->snap_to_terrain)
        return sf_located(L->err, L->file, lift->line, lift->column,
                          "'height_above_ground' places the plant above the terrain at [x, y]; give "
                          "'position' as [x, y] with it, or [x, y, z] without it");
    return 0;
}

int sf_read_plants(loader *L, const ynode *node)
{
    if (!node || ynode_is_null(node)) return 0;
    if (sf_expect_list(L, node, "plants", "- {species: name, position: [x, y]}")) return -1;
    scene_file *sf = L->sf;
    sf->plants = arena_alloc(L->a, (size_t)node->n_items * sizeof *sf->plants + 1);
    const char **names = arena_alloc(L->a, ((size_t)sf->n_species + 1) * sizeof *names);
    if (!sf->plants || !names) return sf_out_of_memory(L);
    for (uint32_t i = 0; i < sf->n_species; i++) names[i] = sf->species[i].name;
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
        if (params_validate(L->a, item, host_schema_plant.params, host_schema_plant.n_params,
                            &scope, &p, L->err))
            return -1;
        plant_spec *pl = &sf->plants[sf->n_plants];
        const sylva_value *species = sylva_param(p, "species"), *pos = sylva_param(p, "position");
        int index = scene_file_species_index(sf, species->s);
        if (index < 0)
            return sf_unknown_name(L, L->file, species, "species", "species", scope.where, names,
                                   sf->n_species);
        pl->species = (uint32_t)index;
        pl->position[0] = pos->list[0], pl->position[1] = pos->list[1];
        pl->position[2] = pos->len == 3 ? pos->list[2] : 0.0;
        pl->snap_to_terrain = pos->len == 2;
        if (read_plant_lift(L, p, pl)) return -1;
        pl->rotation_deg = sylva_param_real(p, "rotation");
        pl->scale = sylva_param_real(p, "scale");
        pl->age = sylva_param_real(p, "age");
        pl->line = item->line, pl->column = item->column;
        sf->n_plants++;
    }
    return 0;
}
