/* scene_file_ztv.c — the ztv: section (what `sylva ztv` maps: observer height, radius, cell,
 * screening and the targets), the developments' names, which objects and targets share, and
 * where the development stands. */
#include "scene_file/scene_file.h"
#include "scene_file/scene_file_loader.h"

#include <math.h>
#include <string.h>

int sf_development_index(loader *L, const char *name, const char *file, uint32_t line, uint32_t column)
{
    scene_file *sf = L->sf;
    for (uint32_t d = 0; d < sf->n_developments; d++)
        if (!strcmp(sf->developments[d], name)) return (int)d;
    if (sf->n_developments == SCENE_MAX_DEVELOPMENTS)
        return sf_located(L->err, file, line, column,
                          "'%s' would be development number %u; a scene names at most %u developments", name,
                          SCENE_MAX_DEVELOPMENTS + 1, SCENE_MAX_DEVELOPMENTS);
    if (!sf->developments) {
        sf->developments = arena_alloc(L->a, SCENE_MAX_DEVELOPMENTS * sizeof *sf->developments);
        if (!sf->developments) return sf_out_of_memory(L);
    }
    sf->developments[sf->n_developments] = name;
    return (int)sf->n_developments++;
}

const char *scene_file_dtm_path(const scene_file *sf)
{
    const terrain_spec *t = &sf->terrain;
    for (uint32_t i = 0; t->params && i < t->params->n; i++)
        if (!strcmp(t->params->spec[i].name, "dtm") && t->params->spec[i].type == SYLVA_P_PATH)
            return t->params->values[i].s;
    return NULL;
}

int scene_file_development_place(const scene_file *sf, double at[2])
{
    double sum[2] = {0, 0};
    uint32_t n = 0;
    for (uint32_t k = 0; k < sf->n_objects; k++)
        if (sf->objects[k].development) sum[0] += sf->objects[k].position[0], sum[1] += sf->objects[k].position[1], n++;
    if (!n)
        for (; n < sf->ztv.n_targets; n++) sum[0] += sf->ztv.targets[n].position[0], sum[1] += sf->ztv.targets[n].position[1];
    if (!n) return -1;
    at[0] = sum[0] / n, at[1] = sum[1] / n;
    return 0;
}

/* targets: a list of {position, height_above_ground, development}. */
static int read_targets(loader *L, const ynode *node)
{
    if (sf_expect_list(L, node, "ztv.targets", "- {position: {easting: E, northing: N}, height_above_ground: 150}"))
        return -1;
    ztv_settings *z = &L->sf->ztv;
    z->targets = arena_alloc(L->a, (size_t)node->n_items * sizeof *z->targets + 1);
    if (!z->targets) return sf_out_of_memory(L);
    static const char *const position_key[] = {"position"};
    uint32_t n_keys;
    const sylva_param_spec *keys = sf_keys_without(L, &host_schema_ztv_target, position_key, 1, &n_keys);
    if (!keys) return -1;
    for (uint32_t i = 0; i < node->n_items; i++) {
        const ynode *item = node->items[i];
        param_scope scope = {L->file, L->dir, sf_arena_printf(L->a, "ztv.targets[%u]", i), position_key, 1,
                             item->line, item->column};
        if (!scope.where) return sf_out_of_memory(L);
        if (item->kind != YNODE_MAPPING)
            return sf_located(L->err, L->file, item->line, item->column,
                              "'%s' must be a mapping (position: ..., height_above_ground: ...), got %s",
                              scope.where, ynode_kind_phrase(item));
        const sylva_params *p;
        sf_position pos;
        if (params_validate(L->a, item, keys, n_keys, &scope, &p, L->err) ||
            sf_read_position(L, item, sf_host_key(&host_schema_ztv_target, "position"), scope.where, &pos))
            return -1;
        const sylva_value *hag = sylva_param(p, "height_above_ground");
        if (pos.has_height && hag->is_set)
            return sf_located(L->err, L->file, hag->line, hag->column,
                              "'%s' has a position with a height and a height_above_ground; give one of them",
                              scope.where);
        ztv_target_spec *t = &z->targets[i];
        memcpy(t->position, pos.local, sizeof t->position);
        t->has_height = pos.has_height;
        t->above_ground = !isnan(pos.above_ground) ? pos.above_ground : hag->r;
        const sylva_value *dev = sylva_param(p, "development");
        const char *name = dev->is_set ? dev->s : L->sf->n_developments ? L->sf->developments[0] : "development";
        int d = sf_development_index(L, name, L->file, dev->is_set ? dev->line : item->line,
                                     dev->is_set ? dev->column : item->column);
        if (d < 0) return -1;
        t->development = (uint32_t)d;
        t->line = item->line, t->column = item->column;
        z->n_targets++;
    }
    return 0;
}

int sf_read_ztv(loader *L)
{
    const ynode_pair *pr = ynode_get_pair(L->root, "ztv");
    ztv_settings *z = &L->sf->ztv;
    z->line = pr ? pr->key_line : L->root->line, z->column = pr ? pr->key_column : L->root->column;
    z->given = pr != NULL;
    static const char *const targets_key[] = {"targets"};
    uint32_t n_keys;
    const sylva_param_spec *keys = sf_keys_without(L, &host_schema_ztv, targets_key, 1, &n_keys);
    if (!keys) return -1;
    param_scope scope = {L->file, L->dir, "ztv", targets_key, 1, z->line, z->column};
    const sylva_params *p;
    if (params_validate(L->a, pr ? pr->value : NULL, keys, n_keys, &scope, &p, L->err)) return -1;
    z->observer_height = sylva_param_real(p, "observer_height");
    double radius = sylva_param_real(p, "radius");
    z->radius = radius > 0 ? radius : INFINITY;
    z->cell = sylva_param_real(p, "cell");
    z->screening = (int)sylva_param(p, "screening")->i;
    z->samples = (uint32_t)sylva_param_int(p, "samples");
    const sylva_value *heights = sylva_param(p, "target_heights");
    if (heights->is_set && !heights->len)
        return sf_located(L->err, L->file, heights->line, heights->column,
                          "'target_heights' is empty; give the heights above the ground, e.g. [150, 270]");
    if (heights->is_set) z->target_heights = heights->list, z->n_target_heights = heights->len;
    const ynode *targets = pr && pr->value->kind == YNODE_MAPPING ? ynode_get(pr->value, "targets") : NULL;
    if (targets && !ynode_is_null(targets)) {
        if (heights->is_set)
            return sf_located(L->err, L->file, heights->line, heights->column,
                              "ztv has both 'targets' and 'target_heights'; give one of them");
        if (read_targets(L, targets)) return -1;
    }
    return 0;
}
