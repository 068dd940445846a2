/* scene_file_objects.c — the objects section: each object a built-in shape, a model file or a
 * group (by name), with its placement (position, rotation, heading, height above ground), name,
 * development flag and material; an entry with `layout:` becomes one object per CSV row. */
#include <math.h>
#include <string.h>

#include "scene_file/scene_file_loader.h"

/* The object's position (pos, read by sf_read_position: local metres or map coordinates) and its
 * height_above_ground key: at a height, above the ground, or on it at the footprint. */
static int read_object_position(loader *L, const sylva_params *p, const sf_position *pos, const char *where,
                                object_spec *o)
{
    const sylva_value *hag = sylva_param(p, "height_above_ground");
    for (int k = 0; k < 3; k++) o->position[k] = pos->local[k];
    int above = !isnan(pos->above_ground);
    if (hag->is_set && (above || (pos->given && pos->has_height)))
        return sf_located(L->err, L->file, hag->line, hag->column,
                          "'%s' gives both a height (in its position) and 'height_above_ground'; give "
                          "position [x, y] with height_above_ground, or [x, y, z] alone", where);
    int at_z = pos->given ? pos->has_height : !hag->is_set; /* no position: [0, 0, 0] */
    o->base = at_z ? OBJECT_AT_Z : (hag->is_set || above) ? OBJECT_ABOVE_GROUND : OBJECT_ON_GROUND;
    o->height_above_ground = hag->is_set ? hag->r : above ? pos->above_ground : 0.0;
    return 0;
}

/* Keys a group's part may not have, since the group is placed as a whole. */
static int check_part_keys(loader *L, const sylva_params *p, const char *where)
{
    static const char *const whole_only[] = {"layout", "development", "development_name", "height_above_ground"};
    for (size_t k = 0; k < sizeof whole_only / sizeof whole_only[0]; k++) {
        const sylva_value *v = sylva_param(p, whole_only[k]);
        if (v->is_set)
            return sf_located(L->err, L->file, v->line, v->column,
                              "'%s' is a part of a group: '%s' belongs on the objects entry that places "
                              "the group", where, whole_only[k]);
    }
    return 0;
}

/* A group's part stands at [x, y, z] in the group's frame, never on the ground or on the map. */
static int check_part_position(loader *L, const sf_position *pos, const char *where)
{
    if (pos->given && (!pos->has_height || !isnan(pos->above_ground)))
        return sf_located(L->err, L->file, pos->line, pos->column,
                          "'%s' is a part of a group: its position is [x, y, z] in the group's frame", where);
    return 0;
}

static int find_group(loader *L, const ynode *item, const char *name, const char *where, uint32_t *out)
{
    const scene_file *sf = L->sf;
    for (uint32_t g = 0; g < sf->n_groups; g++)
        if (!strcmp(sf->groups[g].name, name)) {
            *out = g;
            return 0;
        }
    const ynode *at = ynode_get(item, "group");
    if (!sf->n_groups)
        return sf_located(L->err, L->file, at->line, at->column,
                          "'%s' names group '%s', but the scene has no 'groups:' section", where, name);
    const char *names[64];
    uint32_t n = sf->n_groups < 64 ? sf->n_groups : 64;
    for (uint32_t g = 0; g < n; g++) names[g] = sf->groups[g].name;
    char list[512];
    sf_name_list(names, n, list, sizeof list);
    return sf_located(L->err, L->file, at->line, at->column, "'%s' names group '%s', which is not defined; "
                      "groups are %s", where, name, list);
}

int sf_read_object(loader *L, const ynode *item, const char *where, int part, object_spec *o,
                   const char **layout)
{
    param_scope scope = {L->file, L->dir, where, NULL, 0, item->line, item->column};
    if (item->kind != YNODE_MAPPING)
        return sf_located(L->err, L->file, item->line, item->column,
                          "'%s' must be a mapping (shape: ..., model: ... or group: ..., with position: "
                          "...), got %s", where, ynode_kind_phrase(item));
    const ynode *shape_node = ynode_get(item, "shape"), *model_node = ynode_get(item, "model"),
                *group_node = ynode_get(item, "group");
    int kinds = !!shape_node + !!model_node + !!group_node;
    if (kinds != 1)
        return sf_located(L->err, L->file, item->line, item->column,
                          kinds ? "'%s' gives %s; an object is one of them"
                                : "'%s' needs one of %s (a built-in shape, a model file or a group's name)",
                          where, part ? "shape or model" : "shape, model or group");
    if (part && group_node)
        return sf_located(L->err, L->file, group_node->line, group_node->column,
                          "'%s': a group's part is a shape or a model, not another group", where);
    memset(o, 0, sizeof *o);
    o->file = L->file, o->line = item->line, o->column = item->column;
    static const char *const placed[] = {"position"};
    scope.host_keys = placed, scope.n_host_keys = 1;
    const host_schema *schema = shape_node ? &host_schema_object
                                : model_node ? &host_schema_object_model : &host_schema_object_group;
    uint32_t n_own;
    const sylva_param_spec *own = sf_keys_without(L, schema, placed, 1, &n_own);
    if (!own) return -1;
    sf_position pos;
    if (sf_read_position(L, item, sf_host_key(schema, "position"), where, &pos)) return -1;
    const sylva_params *p;
    if (shape_node) {
        sylva_value kind;
        if (param_value_read(L->a, shape_node, sf_host_key(&host_schema_object, "shape"), &scope, &kind, L->err))
            return -1;
        const host_schema *shape = host_schema_shape((shape_kind)kind.i);
        const sylva_params *sp;
        if (sf_validate_shared(L, item, &scope, own, n_own, shape->params, shape->n_params, "position", &p, &sp) ||
            sf_read_shape(L, L->file, (shape_kind)kind.i, sp, item, &o->shape))
            return -1;
        o->kind = OBJECT_SHAPE;
        sf_copy3(o->scale, sylva_param(p, "scale"));
        if (sf_material_ref(L, L->file, sylva_param(p, "material"), where, &o->material)) return -1;
    } else {
        if (params_validate(L->a, item, own, n_own, &scope, &p, L->err)) return -1;
        o->scale[0] = o->scale[1] = o->scale[2] = 1;
        if (model_node) {
            o->kind = OBJECT_MODEL;
            o->model_path = sylva_param(p, "model")->s;
            o->model_scale = sylva_param_real(p, "scale");
            o->model_up = (int)sylva_param(p, "up_axis")->i;
            const sylva_value *root = sylva_param(p, "model_root");
            if (root->is_set && !(o->model_root = param_resolve_path(L->a, L->dir, root->s)))
                return sf_out_of_memory(L);
        } else {
            o->kind = OBJECT_GROUP;
            if (find_group(L, item, sylva_param(p, "group")->s, where, &o->group)) return -1;
        }
    }
    if (part && (check_part_keys(L, p, where) || check_part_position(L, &pos, where))) return -1;
    const sylva_value *name = sylva_param(p, "name");
    o->name = name->is_set ? name->s : where;
    if (o->kind != OBJECT_GROUP) sf_copy3(o->rotation_deg, sylva_param(p, "rotation"));
    o->heading_deg = sylva_param_real(p, "heading");
    const sylva_value *dev_name = sylva_param(p, "development_name");
    if (dev_name->is_set || sylva_param(p, "development")->i) {
        int d = sf_development_index(L, dev_name->is_set ? dev_name->s : "development", L->file,
                                     dev_name->is_set ? dev_name->line : item->line,
                                     dev_name->is_set ? dev_name->column : item->column);
        if (d < 0) return -1;
        o->development = d + 1;
    }
    if (read_object_position(L, p, &pos, where, o)) return -1;
    const sylva_value *lay = sylva_param(p, "layout");
    *layout = lay->is_set ? lay->s : NULL;
    if (lay->is_set && pos.given)
        return sf_located(L->err, L->file, lay->line, lay->column,
                          "'%s' has a layout, which gives the positions; remove 'position'", where);
    return 0;
}

/* One object per row of the template's layout: the row's id names it, its position, heading
 * and height above ground replace the template's. */
static void place_rows(const object_spec *tpl, const char *csv, const layout_row *rows, uint32_t n,
                       object_spec *out)
{
    for (uint32_t r = 0; r < n; r++) {
        object_spec *o = &out[r];
        *o = *tpl;
        o->name = rows[r].id;
        if (o->base == OBJECT_AT_Z) o->base = OBJECT_ON_GROUND; /* the template gave no position */
        o->position[0] = rows[r].xy[0], o->position[1] = rows[r].xy[1], o->position[2] = 0;
        if (rows[r].has_heading) o->heading_deg = rows[r].heading_deg;
        if (rows[r].has_height) o->base = OBJECT_ABOVE_GROUND, o->height_above_ground = rows[r].height_above_ground;
        o->file = csv, o->line = rows[r].line, o->column = 1;
    }
}

int sf_read_objects(loader *L, const ynode *node)
{
    if (!node || ynode_is_null(node)) return 0;
    if (sf_expect_list(L, node, "objects", "- {shape: box, size: [...], position: [...]}")) return -1;
    scene_file *sf = L->sf;
    uint32_t n = node->n_items;
    object_spec *tpl = arena_alloc(L->a, (size_t)n * sizeof *tpl + 1);
    layout_row **rows = arena_alloc(L->a, (size_t)n * sizeof *rows + 1);
    uint32_t *n_rows = arena_alloc(L->a, (size_t)n * sizeof *n_rows + 1);
    const char **csv = arena_alloc(L->a, (size_t)n * sizeof *csv + 1);
    if (!tpl || !rows || !n_rows || !csv) return sf_out_of_memory(L);
    uint64_t total = 0;
    for (uint32_t i = 0; i < n; i++) {
        const ynode *item = node->items[i];
        const char *where = sf_arena_printf(L->a, "objects[%u]", i), *layout;
        if (!where) return sf_out_of_memory(L);
        if (sf_read_object(L, item, where, 0, &tpl[i], &layout)) return -1;
        n_rows[i] = 1, rows[i] = NULL, csv[i] = NULL;
        if (layout) {
            csv[i] = ynode_get(item, "layout")->text;
            if (sf_read_layout(L, layout, csv[i], &rows[i], &n_rows[i])) return -1;
        }
        total += n_rows[i];
    }
    if (total > 10000000u)
        return sf_located(L->err, L->file, node->line, node->column,
                          "the objects and their layouts place %llu objects; at most 10000000 are placed",
                          (unsigned long long)total);
    sf->objects = arena_alloc(L->a, (size_t)total * sizeof *sf->objects + 1);
    if (!sf->objects) return sf_out_of_memory(L);
    for (uint32_t i = 0; i < n; i++) {
        if (rows[i]) place_rows(&tpl[i], csv[i], rows[i], n_rows[i], &sf->objects[sf->n_objects]);
        else sf->objects[sf->n_objects] = tpl[i];
        sf->n_objects += n_rows[i];
    }
    return 0;
}
