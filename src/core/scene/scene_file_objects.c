/* scene_file_objects.c — the objects section: each object's shape, placement (position,
 * rotation, scale), name and material. */
#include "scene/scene_file_loader.h"

int sf_read_objects(loader *L, const ynode *node)
{
    if (!node || ynode_is_null(node)) return 0;
    if (sf_expect_list(L, node, "objects", "- {shape: box, size: [...], position: [...]}")) return -1;
    scene_file *sf = L->sf;
    sf->objects = arena_alloc(L->a, (size_t)node->n_items * sizeof *sf->objects + 1);
    if (!sf->objects) return sf_out_of_memory(L);
    const sylva_param_spec *os = host_schema_object.params;
    for (uint32_t i = 0; i < node->n_items; i++) {
        const ynode *item = node->items[i];
        param_scope scope = {L->file, L->dir, sf_arena_printf(L->a, "objects[%u]", i), NULL, 0,
                             item->line, item->column};
        if (!scope.where) return sf_out_of_memory(L);
        if (item->kind != YNODE_MAPPING)
            return sf_located(L->err, L->file, item->line, item->column,
                              "'%s' must be a mapping (shape: ..., position: ...), got %s",
                              scope.where, ynode_kind_phrase(item));
        const ynode *shape_node = ynode_get(item, "shape");
        if (!shape_node)
            return sf_located(L->err, L->file, item->line, item->column,
                              "missing required key 'shape' in '%s' (mesh, box, sphere, quad or disk)",
                              scope.where);
        sylva_value kind;
        if (param_value_read(L->a, shape_node, sf_host_key(&host_schema_object, "shape"), &scope,
                             &kind, L->err))
            return -1;
        const host_schema *shape = host_schema_shape((shape_kind)kind.i);
        const sylva_params *p, *sp;
        if (sf_validate_shared(L, item, &scope, os, host_schema_object.n_params, shape->params,
                               shape->n_params, NULL, &p, &sp))
            return -1;
        object_spec *o = &sf->objects[sf->n_objects];
        const sylva_value *name = sylva_param(p, "name");
        o->name = name->is_set ? name->s : scope.where;
        if (sf_read_shape(L, L->file, (shape_kind)kind.i, sp, item, &o->shape)) return -1;
        sf_copy3(o->position, sylva_param(p, "position"));
        sf_copy3(o->rotation_deg, sylva_param(p, "rotation"));
        sf_copy3(o->scale, sylva_param(p, "scale"));
        if (sf_material_ref(L, L->file, sylva_param(p, "material"), scope.where, &o->material))
            return -1;
        o->line = item->line, o->column = item->column;
        sf->n_objects++;
    }
    return 0;
}
