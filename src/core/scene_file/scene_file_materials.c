/* scene_file_materials.c — the materials section (each material's type, albedo,
 * transmittance for leaves, texture and alpha mask) and references to materials by name from
 * the terrain, species and objects. */
#include "scene_file/scene_file.h"
#include "scene_file/scene_file_loader.h"

/* Checks that a material key names a defined material; *out is the name or NULL when unset. */
int sf_material_ref(loader *L, const char *file, const sylva_value *v, const char *where,
                    const char **out)
{
    *out = NULL;
    if (!v || !v->is_set) return 0;
    if (scene_file_material_index(L->sf, v->s) < 0) {
        const char **names = arena_alloc(L->a, ((size_t)L->sf->n_materials + 1) * sizeof *names);
        if (!names) return sf_out_of_memory(L);
        for (uint32_t i = 0; i < L->sf->n_materials; i++) names[i] = L->sf->materials[i].name;
        return sf_unknown_name(L, file, v, "material", "materials", where, names, L->sf->n_materials);
    }
    *out = v->s;
    return 0;
}

int sf_read_materials(loader *L, const ynode *node)
{
    if (!node || ynode_is_null(node)) return 0;
    if (node->kind != YNODE_MAPPING)
        return sf_located(L->err, L->file, node->line, node->column,
                          "'materials' must be a mapping of names to materials (grass: {type: "
                          "lambert, albedo: [...]}), got %s", ynode_kind_phrase(node));
    scene_file *sf = L->sf;
    sf->materials = arena_alloc(L->a, (size_t)node->n_pairs * sizeof *sf->materials + 1);
    if (!sf->materials) return sf_out_of_memory(L);
    for (uint32_t i = 0; i < node->n_pairs; i++) {
        const ynode_pair *pr = &node->pairs[i];
        param_scope scope = {L->file, L->dir, sf_arena_printf(L->a, "materials.%s", pr->key), NULL, 0,
                             pr->key_line, pr->key_column};
        const sylva_params *p;
        if (!scope.where) return sf_out_of_memory(L);
        if (params_validate(L->a, pr->value, host_schema_material.params,
                            host_schema_material.n_params, &scope, &p, L->err))
            return -1;
        material_spec *m = &sf->materials[sf->n_materials++];
        const sylva_value *type = sylva_param(p, "type"), *alb = sylva_param(p, "albedo"),
                          *tr = sylva_param(p, "transmittance"), *tex = sylva_param(p, "texture"),
                          *mask = sylva_param(p, "alpha_mask");
        m->name = pr->key;
        if (name_index_add(&sf->material_names, m->name, sf->n_materials - 1) < 0) return sf_out_of_memory(L);
        m->bsdf = (sylva_bsdf)(type->i + 1);
        m->line = pr->key_line, m->column = pr->key_column;
        sf_copy3(m->albedo, alb);
        sf_copy3(m->transmittance, tr);
        m->texture_path = tex->s;
        m->alpha_mask = (int)mask->i;
        if (m->bsdf != SYLVA_BSDF_LEAF && tr->is_set)
            return sf_located(L->err, L->file, tr->line, tr->column,
                              "'transmittance' applies only to type: leaf; material '%s' is %s",
                              m->name, type->s);
        for (int k = 0; k < 3 && m->bsdf == SYLVA_BSDF_LEAF; k++)
            if (m->albedo[k] + m->transmittance[k] > 1.0) {
                const sylva_value *at = tr->is_set ? tr : alb;
                return sf_located(L->err, L->file, at->line ? at->line : pr->key_line,
                                  at->line ? at->column : pr->key_column,
                                  "albedo + transmittance of leaf material '%s' must be at most 1 "
                                  "in each channel, got %.15g + %.15g in channel %d",
                                  m->name, m->albedo[k], m->transmittance[k], k);
            }
        if (m->alpha_mask && !m->texture_path)
            return sf_located(L->err, L->file, mask->line, mask->column,
                              "'alpha_mask' of material '%s' needs a 'texture' whose alpha it uses",
                              m->name);
    }
    return 0;
}
