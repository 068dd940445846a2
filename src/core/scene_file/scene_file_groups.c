/* scene_file_groups.c — the groups section: named lists of parts (shapes or models at
 * positions of the group's own frame) that an objects entry places as one object. */
#include <string.h>

#include "scene_file/scene_file_loader.h"

int sf_read_groups(loader *L, const ynode *node)
{
    if (!node || ynode_is_null(node)) return 0;
    if (node->kind != YNODE_MAPPING)
        return sf_located(L->err, L->file, node->line, node->column,
                          "'groups' must be a mapping of group names to lists of parts (turbine: [{model: "
                          "tower.stl}, ...]), got %s", ynode_kind_phrase(node));
    scene_file *sf = L->sf;
    sf->groups = arena_alloc(L->a, (size_t)node->n_pairs * sizeof *sf->groups + 1);
    if (!sf->groups) return sf_out_of_memory(L);
    for (uint32_t g = 0; g < node->n_pairs; g++) {
        const ynode_pair *pr = &node->pairs[g];
        const ynode *list = pr->value;
        const char *where = sf_arena_printf(L->a, "groups.%s", pr->key);
        if (!where) return sf_out_of_memory(L);
        if (list->kind != YNODE_SEQUENCE || !list->n_items)
            return sf_located(L->err, L->file, list->line, list->column,
                              "'%s' must be a list of one or more parts (- {model: ..., position: [x, y, z]}), "
                              "got %s", where, ynode_kind_phrase(list));
        group_spec *gs = &sf->groups[g];
        *gs = (group_spec){.name = pr->key, .line = pr->key_line, .column = pr->key_column};
        gs->parts = arena_alloc(L->a, (size_t)list->n_items * sizeof *gs->parts);
        if (!gs->parts) return sf_out_of_memory(L);
        for (uint32_t i = 0; i < list->n_items; i++) {
            const char *part = sf_arena_printf(L->a, "%s[%u]", where, i), *layout;
            if (!part) return sf_out_of_memory(L);
            if (sf_read_object(L, list->items[i], part, 1, &gs->parts[i], &layout)) return -1;
            gs->n_parts++;
        }
        sf->n_groups++;
    }
    return 0;
}
