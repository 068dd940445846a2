/* scene_file.c — reading a scene file into a scene_file: sections, cross-references, includes.
 *
 * The YAML tree (yaml_doc) is checked section by section against the host's schemas
 * (host_schema) and each plugin block against its plugin's schema (plugin_registry_find); keys
 * of a mapping that two schemas share (a species' host keys and its tree plugin's keys, an
 * object's keys and its shape's keys) are validated in two passes, each skipping the other's
 * keys. Rules between keys (look_at or direction, grid or plugin, material names, species
 * names) are checked here, each at the location of the key that breaks them. No plugin code
 * beyond the registry's descriptor lookup runs.
 *
 * Sections are read in a fixed order: image, camera, sun, sky, materials, ecology, terrain,
 * species (with includes), plants, objects — materials before their users, the ecology before
 * the species blocks it defines, species before plants.
 */
#include "scene/scene_file.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "params/validate.h"
#include "plugin/plugin_host.h"
#include "scene/host_schema.h"
#include "scene/scene_estimate.h"
#include "params/yaml_doc.h"
#include "util/arena.h"

#define INCLUDE_MAX_DEPTH 16
#define DEG (M_PI / 180.0)

/* A species as found in the scene file or an included file, before validation. */
typedef struct species_entry {
    const char *name;
    const ynode *node;
    uint32_t line, column;  /* of the name */
    const char *file, *dir; /* the file that defines it, for messages and paths */
} species_entry;

typedef struct included_file {
    const char *real;       /* canonical path */
    const char *file;       /* as named in messages */
    uint32_t line, column;  /* where it was included (0 for the scene file itself) */
    const char *from;       /* the including file */
} included_file;

typedef struct loader {
    arena *a;
    const plugin_registry *reg;
    err_buf *err;
    scene_file *sf;
    const char *file, *dir;      /* the scene file: name in messages, absolute folder */
    const ynode *root;

    species_entry *entries;
    uint32_t n_entries, cap_entries;
    included_file chain[INCLUDE_MAX_DEPTH + 1]; /* the include chain from the scene file down */
    uint32_t chain_len;
    included_file *seen;         /* every file read so far */
    uint32_t n_seen, cap_seen;

    const sylva_plugin *ecology; /* NULL: the scene has no ecology block */
    const char *species_section; /* the ecology plugin's species_section, or "ecology" */
} loader;

static int located(err_buf *err, const char *file, uint32_t line, uint32_t column,
                   const char *fmt, ...) __attribute__((format(printf, 5, 6)));
static int located(err_buf *err, const char *file, uint32_t line, uint32_t column,
                   const char *fmt, ...)
{
    char msg[ERR_MSG_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return err_set(err, "%s:%u:%u: %s", file, line, column, msg);
}

static int out_of_memory(loader *L)
{
    return err_set(L->err, "%s: out of memory while loading", L->file);
}

static const char *arena_printf(arena *a, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
static const char *arena_printf(arena *a, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (n < 0) return NULL;
    char *s = arena_alloc(a, (size_t)n + 1);
    if (!s) return NULL;
    va_start(ap, fmt);
    vsnprintf(s, (size_t)n + 1, fmt, ap);
    va_end(ap);
    return s;
}

/* Names of a schema's keys followed by extra names, NULL entries dropped. */
static const char **key_names(arena *a, const sylva_param_spec *spec, uint32_t n,
                              const char *const *extra, uint32_t n_extra, uint32_t *count)
{
    const char **names = arena_alloc(a, ((size_t)n + n_extra + 1) * sizeof *names);
    if (!names) return NULL;
    uint32_t k = 0;
    for (uint32_t i = 0; i < n; i++) names[k++] = spec[i].name;
    for (uint32_t i = 0; i < n_extra; i++)
        if (extra[i]) names[k++] = extra[i];
    *count = k;
    return names;
}

/* Validates a mapping that two schemas share: `own` (host keys) and `other` (a plugin's or a
 * shape's keys), plus an optional extra key owned by neither (the species' ecology block). */
static int validate_shared(loader *L, const ynode *map, const param_scope *base,
                           const sylva_param_spec *own, uint32_t n_own,
                           const sylva_param_spec *other, uint32_t n_other, const char *extra,
                           const sylva_params **own_out, const sylva_params **other_out)
{
    uint32_t n1, n2;
    const char **other_keys = key_names(L->a, other, n_other, &extra, 1, &n1);
    const char **own_keys = key_names(L->a, own, n_own, &extra, 1, &n2);
    if (!other_keys || !own_keys) return out_of_memory(L);
    param_scope s1 = *base, s2 = *base;
    s1.host_keys = other_keys, s1.n_host_keys = n1;
    s2.host_keys = own_keys, s2.n_host_keys = n2;
    if (params_validate(L->a, map, own, n_own, &s1, own_out, L->err)) return -1;
    return params_validate(L->a, map, other, n_other, &s2, other_out, L->err);
}

static void copy3(double out[3], const sylva_value *v)
{
    for (int k = 0; k < 3; k++) out[k] = v->list[k];
}

static double length3(const double v[3]) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

/* Scales v to unit length without overflow or underflow (components of 1e300 or 1e-320 give a
 * direction too); returns 0, or -1 when v is zero or not finite. */
static int normalize3(double v[3])
{
    double m = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
    if (!(m > 0.0) || !isfinite(m)) return -1;
    for (int k = 0; k < 3; k++) v[k] /= m;
    double l = length3(v);
    for (int k = 0; k < 3; k++) v[k] /= l;
    return 0;
}

/* The renderer works in single precision: a coordinate beyond its range becomes infinite. */
static int beyond_float(const double v[3])
{
    return fabs(v[0]) > FLT_MAX || fabs(v[1]) > FLT_MAX || fabs(v[2]) > FLT_MAX;
}

/* The spec of one host key (tables are static; every name asked for exists). */
static const sylva_param_spec *host_key(const host_schema *schema, const char *name)
{
    for (uint32_t k = 0; k < schema->n_params; k++)
        if (!strcmp(schema->params[k].name, name)) return &schema->params[k];
    return &schema->params[0];
}

/* A list of names for messages: "a, b, c" (cut when long). */
static void name_list(const char *const *names, uint32_t n, char *buf, size_t size)
{
    size_t used = 0;
    buf[0] = '\0';
    for (uint32_t k = 0; k < n && used < size; k++)
        used += (size_t)snprintf(buf + used, size - used, "%s%s", k ? ", " : "", names[k]);
}

/* --- materials ------------------------------------------------------------------------------ */

int scene_file_material_index(const scene_file *sf, const char *name)
{
    for (uint32_t i = 0; sf && name && i < sf->n_materials; i++)
        if (!strcmp(sf->materials[i].name, name)) return (int)i;
    return -1;
}

int scene_file_species_index(const scene_file *sf, const char *name)
{
    for (uint32_t i = 0; sf && name && i < sf->n_species; i++)
        if (!strcmp(sf->species[i].name, name)) return (int)i;
    return -1;
}

/* An unknown name of a `kind` ("material", "species") among the defined ones. */
static int unknown_name(loader *L, const char *file, const sylva_value *v, const char *kind,
                        const char *plural, const char *where, const char *const *defined,
                        uint32_t n_defined)
{
    const char *near = param_nearest_name(v->s, defined, n_defined);
    if (near)
        return located(L->err, file, v->line, v->column,
                       "unknown %s '%s' in '%s'; did you mean '%s'?", kind, v->s, where, near);
    if (!n_defined)
        return located(L->err, file, v->line, v->column,
                       "unknown %s '%s' in '%s'; the scene defines no %s", kind, v->s, where,
                       plural);
    char list[1024];
    name_list(defined, n_defined, list, sizeof list);
    return located(L->err, file, v->line, v->column, "unknown %s '%s' in '%s'; defined %s are %s",
                   kind, v->s, where, plural, list);
}

/* Checks that a material key names a defined material; *out is the name or NULL when unset. */
static int material_ref(loader *L, const char *file, const sylva_value *v, const char *where,
                        const char **out)
{
    *out = NULL;
    if (!v || !v->is_set) return 0;
    if (scene_file_material_index(L->sf, v->s) < 0) {
        const char **names = arena_alloc(L->a, ((size_t)L->sf->n_materials + 1) * sizeof *names);
        if (!names) return out_of_memory(L);
        for (uint32_t i = 0; i < L->sf->n_materials; i++) names[i] = L->sf->materials[i].name;
        return unknown_name(L, file, v, "material", "materials", where, names, L->sf->n_materials);
    }
    *out = v->s;
    return 0;
}

static int read_materials(loader *L, const ynode *node)
{
    if (!node || ynode_is_null(node)) return 0;
    if (node->kind != YNODE_MAPPING)
        return located(L->err, L->file, node->line, node->column,
                       "'materials' must be a mapping of names to materials (grass: {type: "
                       "lambert, albedo: [...]}), got %s", ynode_kind_phrase(node));
    scene_file *sf = L->sf;
    sf->materials = arena_alloc(L->a, (size_t)node->n_pairs * sizeof *sf->materials + 1);
    if (!sf->materials) return out_of_memory(L);
    for (uint32_t i = 0; i < node->n_pairs; i++) {
        const ynode_pair *pr = &node->pairs[i];
        param_scope scope = {L->file, L->dir, arena_printf(L->a, "materials.%s", pr->key), NULL, 0,
                             pr->key_line, pr->key_column};
        const sylva_params *p;
        if (!scope.where) return out_of_memory(L);
        if (params_validate(L->a, pr->value, host_schema_material.params,
                            host_schema_material.n_params, &scope, &p, L->err))
            return -1;
        material_spec *m = &sf->materials[sf->n_materials++];
        const sylva_value *type = sylva_param(p, "type"), *alb = sylva_param(p, "albedo"),
                          *tr = sylva_param(p, "transmittance"), *tex = sylva_param(p, "texture"),
                          *mask = sylva_param(p, "alpha_mask");
        m->name = pr->key;
        m->bsdf = (sylva_bsdf)(type->i + 1);
        m->line = pr->key_line, m->column = pr->key_column;
        copy3(m->albedo, alb);
        copy3(m->transmittance, tr);
        m->texture_path = tex->s;
        m->alpha_mask = (int)mask->i;
        if (m->bsdf != SYLVA_BSDF_LEAF && tr->is_set)
            return located(L->err, L->file, tr->line, tr->column,
                           "'transmittance' applies only to type: leaf; material '%s' is %s",
                           m->name, type->s);
        for (int k = 0; k < 3 && m->bsdf == SYLVA_BSDF_LEAF; k++)
            if (m->albedo[k] + m->transmittance[k] > 1.0) {
                const sylva_value *at = tr->is_set ? tr : alb;
                return located(L->err, L->file, at->line ? at->line : pr->key_line,
                               at->line ? at->column : pr->key_column,
                               "albedo + transmittance of leaf material '%s' must be at most 1 "
                               "in each channel, got %.15g + %.15g in channel %d",
                               m->name, m->albedo[k], m->transmittance[k], k);
            }
        if (m->alpha_mask && !m->texture_path)
            return located(L->err, L->file, mask->line, mask->column,
                           "'alpha_mask' of material '%s' needs a 'texture' whose alpha it uses",
                           m->name);
    }
    return 0;
}

/* --- plugins -------------------------------------------------------------------------------- */

/* Looks up the plugin named in map's `plugin:` key (spec: the host table's `plugin` entry). */
static int find_plugin(loader *L, const param_scope *scope, const ynode_pair *pair,
                       const sylva_param_spec *plugin_spec, sylva_kind kind,
                       const sylva_plugin **out, const char **name_out)
{
    sylva_value v;
    if (param_value_read(L->a, pair->value, plugin_spec, scope, &v, L->err)) return -1;
    const char *kind_name = plugin_kind_name(kind);
    if (!L->reg)
        return located(L->err, scope->file, v.line, v.column,
                       "%s plugin '%s' cannot be used: no plugins are available (the scene was "
                       "loaded without a plugin registry)",
                       kind_name, v.s);
    err_buf e;
    err_clear(&e);
    const loaded_plugin *lp = plugin_registry_find(L->reg, v.s, kind, &e);
    if (!lp)
        return located(L->err, scope->file, v.line, v.column, "%s",
                       e.msg[0] ? e.msg : "no such plugin");
    const sylva_plugin *d = lp->desc;
    const char *clash = host_reserved_key_clash(d->params, d->n_params, L->species_section);
    if (clash)
        return located(L->err, scope->file, v.line, v.column,
                       "%s plugin '%s' (%s) cannot be used: its parameter '%s' has a name the "
                       "host keeps for itself (plugin, material, variants, shape, grid, origin, "
                       "spacing, include, %s); the plugin must rename it",
                       kind_name, v.s, lp->file, clash,
                       L->species_section ? L->species_section : "ecology");
    *out = d;
    *name_out = v.s;
    return 0;
}

static int read_ecology(loader *L, const ynode *node, uint32_t line, uint32_t column)
{
    L->species_section = "ecology";
    if (!node || ynode_is_null(node)) return 0;
    param_scope scope = {L->file, L->dir, "ecology", NULL, 0, line, column};
    if (node->kind != YNODE_MAPPING)
        return located(L->err, L->file, node->line, node->column,
                       "'ecology' must be a mapping (plugin: NAME and the plugin's keys), got %s",
                       ynode_kind_phrase(node));
    const ynode_pair *pp = ynode_get_pair(node, "plugin");
    if (!pp)
        return located(L->err, L->file, node->line, node->column,
                       "missing required key 'plugin' in 'ecology' (the ecology plugin to use)");
    const sylva_plugin *d;
    const char *name;
    if (find_plugin(L, &scope, pp, host_key(&host_schema_ecology, "plugin"), SYLVA_KIND_ECOLOGY, &d,
                    &name))
        return -1;
    const sylva_params *host, *params;
    if (validate_shared(L, node, &scope, host_schema_ecology.params, host_schema_ecology.n_params,
                        d->params, d->n_params, NULL, &host, &params))
        return -1;
    L->ecology = d;
    if (d->species_section) L->species_section = d->species_section;
    L->sf->ecology.plugin = name;
    L->sf->ecology.params = params;
    L->sf->ecology.line = node->line, L->sf->ecology.column = node->column;
    return 0;
}

/* --- terrain -------------------------------------------------------------------------------- */

static int read_terrain(loader *L, const ynode *node, uint32_t line, uint32_t column)
{
    terrain_spec *t = &L->sf->terrain;
    if (!node || ynode_is_null(node)) return 0;
    param_scope scope = {L->file, L->dir, "terrain", NULL, 0, line, column};
    const sylva_params *host;
    if (node->kind != YNODE_MAPPING)
        return located(L->err, L->file, node->line, node->column,
                       "'terrain' must be a mapping (grid: ... or plugin: ...), got %s",
                       ynode_kind_phrase(node));
    t->line = node->line, t->column = node->column;
    const ynode_pair *pp = ynode_get_pair(node, "plugin");
    if (pp) {
        const sylva_plugin *d;
        if (find_plugin(L, &scope, pp, host_key(&host_schema_terrain, "plugin"), SYLVA_KIND_TERRAIN,
                        &d, &t->plugin))
            return -1;
        if (validate_shared(L, node, &scope, host_schema_terrain.params,
                            host_schema_terrain.n_params, d->params, d->n_params, NULL, &host,
                            &t->params))
            return -1;
        static const char *const inline_keys[] = {"grid", "origin", "spacing"};
        for (int k = 0; k < 3; k++) {
            const sylva_value *v = sylva_param(host, inline_keys[k]);
            if (v->is_set)
                return located(L->err, L->file, v->line, v->column,
                               "'%s' belongs to an inline terrain; with plugin: the plugin '%s' "
                               "builds the heights (remove '%s' or 'plugin')",
                               inline_keys[k], t->plugin, inline_keys[k]);
        }
        t->source = TERRAIN_PLUGIN;
    } else {
        if (params_validate(L->a, node, host_schema_terrain.params, host_schema_terrain.n_params,
                            &scope, &host, L->err))
            return -1;
        const sylva_value *grid = sylva_param(host, "grid");
        if (!grid->is_set)
            return located(L->err, L->file, node->line, node->column,
                           "'terrain' needs either 'grid' (inline heights) or 'plugin' (a "
                           "terrain plugin)");
        if (grid->rows < 2 || grid->cols < 2)
            return located(L->err, L->file, grid->line, grid->column,
                           "'grid' needs at least 2 rows and 2 columns of heights, got %u x %u",
                           grid->rows, grid->cols);
        const sylva_value *origin = sylva_param(host, "origin"),
                          *spacing = sylva_param(host, "spacing");
        t->source = TERRAIN_GRID;
        t->grid = grid->list, t->nx = grid->cols, t->ny = grid->rows;
        t->origin[0] = origin->list[0], t->origin[1] = origin->list[1];
        t->spacing[0] = spacing->list[0], t->spacing[1] = spacing->list[1];
    }
    return material_ref(L, L->file, sylva_param(host, "material"), "terrain", &t->material);
}

/* --- shapes --------------------------------------------------------------------------------- */

/* Fills a shape_spec from validated shape keys; mesh indices and column counts are checked
 * against the nodes in `map` so messages point at the offending number. */
static int read_shape(loader *L, const char *file, shape_kind kind, const sylva_params *p,
                      const ynode *map, shape_spec *s)
{
    memset(s, 0, sizeof *s);
    s->kind = kind;
    switch (kind) {
    case SHAPE_BOX:
        copy3(s->size, sylva_param(p, "size"));
        return 0;
    case SHAPE_SPHERE:
        s->radius = sylva_param_real(p, "radius");
        s->subdivisions = (uint32_t)sylva_param_int(p, "subdivisions");
        return 0;
    case SHAPE_QUAD: {
        const sylva_value *size = sylva_param(p, "size");
        s->size[0] = size->list[0], s->size[1] = size->list[1];
        return 0;
    }
    case SHAPE_DISK:
        s->radius = sylva_param_real(p, "radius");
        s->subdivisions = (uint32_t)sylva_param_int(p, "segments");
        return 0;
    case SHAPE_MESH:
        break;
    }
    const sylva_value *vtx = sylva_param(p, "vertices"), *tri = sylva_param(p, "triangles"),
                      *uv = sylva_param(p, "uvs");
    if (vtx->cols != 3)
        return located(L->err, file, vtx->line, vtx->column,
                       "'vertices' must be rows of 3 numbers [x, y, z], got rows of %u", vtx->cols);
    if (tri->cols != 3)
        return located(L->err, file, tri->line, tri->column,
                       "'triangles' must be rows of 3 vertex indices [i, j, k], got rows of %u",
                       tri->cols);
    const ynode *tri_node = ynode_get(map, "triangles");
    for (uint32_t r = 0; r < tri->rows; r++)
        for (uint32_t c = 0; c < 3; c++) {
            double x = tri->list[(size_t)r * 3 + c];
            if (floor(x) != x || x >= vtx->rows) {
                const ynode *at = tri_node->items[r]->items[c];
                return located(L->err, file, at->line, at->column,
                               "'triangles'[%u][%u] must be a vertex index, an integer in [0, %u], "
                               "got %s",
                               r, c, vtx->rows - 1, at->text);
            }
        }
    if (uv->is_set && (uv->cols != 2 || uv->rows != vtx->rows))
        return located(
            L->err, file, uv->line, uv->column,
            "'uvs' must be %u rows of 2 numbers [u, v] (one per vertex), got %u rows of %u",
            vtx->rows, uv->rows, uv->cols);
    s->vertices = vtx->list, s->n_vertices = vtx->rows;
    s->triangles = tri->list, s->n_triangles = tri->rows;
    if (uv->is_set) s->uvs = uv->list, s->n_uvs = uv->rows;
    return 0;
}

/* --- species -------------------------------------------------------------------------------- */

static int add_entry(loader *L, const ynode_pair *pr, const char *file, const char *dir)
{
    for (uint32_t i = 0; i < L->n_entries; i++)
        if (!strcmp(L->entries[i].name, pr->key))
            return located(L->err, file, pr->key_line, pr->key_column,
                           "species '%s' is defined twice; it was first defined at %s:%u:%u",
                           pr->key, L->entries[i].file, L->entries[i].line, L->entries[i].column);
    if (L->n_entries == L->cap_entries) {
        uint32_t cap = L->cap_entries ? 2 * L->cap_entries : 16;
        species_entry *e = arena_alloc(L->a, (size_t)cap * sizeof *e);
        if (!e) return out_of_memory(L);
        if (L->n_entries) memcpy(e, L->entries, (size_t)L->n_entries * sizeof *e);
        L->entries = e, L->cap_entries = cap;
    }
    L->entries[L->n_entries++] = (species_entry){pr->key, pr->value, pr->key_line, pr->key_column,
                                                 file, dir};
    return 0;
}

static const char *folder_of(arena *a, const char *path)
{
    const char *slash = strrchr(path, '/');
    if (!slash) return arena_strdup(a, ".");
    if (slash == path) return arena_strdup(a, "/");
    return arena_strndup(a, path, (size_t)(slash - path));
}

static int collect_species(loader *L, const ynode *map, const char *file, const char *dir);

/* Reads one included file (named by the scalar `item`) and collects its species. */
static int include_file(loader *L, const ynode *item, const char *file, const char *dir)
{
    if (item->kind != YNODE_SCALAR || ynode_is_null(item) || !item->text[0])
        return located(L->err, file, item->line, item->column,
                       "'include' takes file names (a string or a list of strings), got %s",
                       ynode_kind_phrase(item));
    const char *rel = item->text;
    const char *path = param_resolve_path(L->a, dir, rel);
    /* messages name the file as the user would reach it from the scene file's location */
    const char *shown_dir = strchr(file, '/') ? folder_of(L->a, file) : NULL;
    const char *shown = rel[0] == '/' || !shown_dir ? arena_strdup(L->a, rel)
                                                    : param_resolve_path(L->a, shown_dir, rel);
    if (!path || !shown) return out_of_memory(L);
    char *real = realpath(path, NULL); /* malloc'ed; copied into the arena and freed below */
    if (!real)
        return located(L->err, file, item->line, item->column, "cannot include '%s': %s", rel,
                       strerror(errno));
    const char *canon = arena_strdup(L->a, real);
    free(real);
    if (!canon) return out_of_memory(L);

    for (uint32_t i = 0; i < L->chain_len; i++)
        if (!strcmp(L->chain[i].real, canon)) {
            char trail[1024];
            size_t used = 0;
            for (uint32_t k = i; k < L->chain_len && used < sizeof trail; k++)
                used += (size_t)snprintf(trail + used, sizeof trail - used, "%s includes ",
                                         L->chain[k].file);
            return located(L->err, file, item->line, item->column,
                           "include cycle: %s%s again", trail, L->chain[i].file);
        }
    for (uint32_t i = 0; i < L->n_seen; i++)
        if (!strcmp(L->seen[i].real, canon))
            return located(L->err, file, item->line, item->column,
                           "'%s' is already included (at %s:%u:%u); include a file once", rel,
                           L->seen[i].from, L->seen[i].line, L->seen[i].column);
    if (L->chain_len > INCLUDE_MAX_DEPTH)
        return located(L->err, file, item->line, item->column,
                       "includes nest deeper than the limit of %d files", INCLUDE_MAX_DEPTH);

    if (L->n_seen == L->cap_seen) {
        uint32_t cap = L->cap_seen ? 2 * L->cap_seen : 8;
        included_file *s = arena_alloc(L->a, (size_t)cap * sizeof *s);
        if (!s) return out_of_memory(L);
        if (L->n_seen) memcpy(s, L->seen, (size_t)L->n_seen * sizeof *s);
        L->seen = s, L->cap_seen = cap;
    }
    included_file inc = {canon, shown, item->line, item->column, file};
    L->seen[L->n_seen++] = inc;

    yaml_doc doc;
    int rc = yaml_doc_load(L->a, path, shown, &doc, L->err);
    if (rc == YAML_DOC_UNREADABLE)
        return err_prefix(L->err, "%s:%u:%u: cannot include '%s': ", file, item->line,
                          item->column, rel);
    if (rc) return -1;
    if (!doc.root || doc.root->kind != YNODE_MAPPING)
        return located(L->err, shown, doc.root ? doc.root->line : 1,
                       doc.root ? doc.root->column : 1,
                       "an included species file must hold a mapping with a 'species:' section, "
                       "got %s",
                       ynode_kind_phrase(doc.root));
    for (uint32_t i = 0; i < doc.root->n_pairs; i++) {
        const ynode_pair *pr = &doc.root->pairs[i];
        if (strcmp(pr->key, "species"))
            return located(L->err, shown, pr->key_line, pr->key_column,
                           "an included file holds only a 'species:' section; '%s' belongs in "
                           "the scene file", pr->key);
    }
    const ynode *species = ynode_get(doc.root, "species");
    if (!species)
        return located(L->err, shown, doc.root->line, doc.root->column,
                       "an included species file must hold a 'species:' section");
    const char *inc_dir = folder_of(L->a, canon);
    if (!inc_dir) return out_of_memory(L);
    L->chain[L->chain_len++] = inc;
    rc = collect_species(L, species, shown, inc_dir);
    L->chain_len--;
    return rc;
}

/* Gathers the species of one `species:` mapping, expanding `include:` where it stands. */
static int collect_species(loader *L, const ynode *map, const char *file, const char *dir)
{
    if (ynode_is_null(map)) return 0;
    if (map->kind != YNODE_MAPPING)
        return located(L->err, file, map->line, map->column,
                       "'species' must be a mapping of names to species (beech: {plugin: ...}), "
                       "got %s", ynode_kind_phrase(map));
    for (uint32_t i = 0; i < map->n_pairs; i++) {
        const ynode_pair *pr = &map->pairs[i];
        if (strcmp(pr->key, "include")) {
            if (!pr->key[0])
                return located(L->err, file, pr->key_line, pr->key_column,
                               "a species needs a name, got an empty key");
            if (add_entry(L, pr, file, dir)) return -1;
            continue;
        }
        const ynode *inc = pr->value;
        if (inc->kind == YNODE_SEQUENCE) {
            for (uint32_t k = 0; k < inc->n_items; k++)
                if (include_file(L, inc->items[k], file, dir)) return -1;
        } else if (include_file(L, inc, file, dir)) {
            return -1;
        }
    }
    return 0;
}

static int read_species_entry(loader *L, const species_entry *e, species_spec *sp)
{
    const char *file = e->file;
    param_scope scope = {file, e->dir, arena_printf(L->a, "species.%s", e->name), NULL, 0,
                         e->line, e->column};
    if (!scope.where) return out_of_memory(L);
    const ynode *map = e->node;
    if (map->kind != YNODE_MAPPING)
        return located(L->err, file, map->line, map->column,
                       "species '%s' must be a mapping (plugin: ... or shape: ...), got %s",
                       e->name, ynode_kind_phrase(map));
    sp->name = e->name;
    sp->line = e->line, sp->column = e->column;
    const ynode_pair *pp = ynode_get_pair(map, "plugin"), *shp = ynode_get_pair(map, "shape");
    if (pp && shp)
        return located(L->err, file, shp->key_line, shp->key_column,
                       "species '%s' gives both 'plugin' and 'shape'; give one of them", e->name);
    if (!pp && !shp)
        return located(L->err, file, map->line, map->column,
                       "species '%s' needs 'plugin' (a tree plugin) or 'shape' (mesh, box, "
                       "sphere, quad or disk)", e->name);
    const sylva_params *host;
    const sylva_param_spec *hs = host_schema_species.params;
    uint32_t hn = host_schema_species.n_params;
    const char *section = L->species_section;
    if (pp) {
        const sylva_plugin *d;
        if (find_plugin(L, &scope, pp, host_key(&host_schema_species, "plugin"), SYLVA_KIND_TREE,
                        &d, &sp->plugin))
            return -1;
        if (validate_shared(L, map, &scope, hs, hn, d->params, d->n_params, section, &host,
                            &sp->params))
            return -1;
        const sylva_value *mat = sylva_param(host, "material");
        if (mat->is_set)
            return located(L->err, file, mat->line, mat->column,
                           "'material' applies to built-in shapes; tree plugin '%s' makes its "
                           "own materials", sp->plugin);
        sp->variants = (uint32_t)sylva_param_int(host, "variants");
    } else {
        sylva_value kind;
        if (param_value_read(L->a, shp->value, host_key(&host_schema_species, "shape"), &scope,
                             &kind, L->err))
            return -1;
        const host_schema *shape = host_schema_shape((shape_kind)kind.i);
        const sylva_params *shape_params;
        if (validate_shared(L, map, &scope, hs, hn, shape->params, shape->n_params, section,
                            &host, &shape_params))
            return -1;
        const sylva_value *variants = sylva_param(host, "variants");
        if (variants->is_set)
            return located(L->err, file, variants->line, variants->column,
                           "'variants' applies to plugin species; a built-in shape has one form");
        if (read_shape(L, file, (shape_kind)kind.i, shape_params, map, &sp->shape)) return -1;
        if (material_ref(L, file, sylva_param(host, "material"), scope.where, &sp->material))
            return -1;
        sp->variants = 1;
    }
    const ynode_pair *eco = ynode_get_pair(map, section);
    if (!eco) {
        /* A species without a block takes the ecology plugin's defaults, so the plugin always
         * receives a complete block for every species. */
        if (!L->ecology || !L->ecology->species_section) return 0;
        param_scope ds = {file, e->dir, arena_printf(L->a, "species.%s.%s", e->name, section), NULL, 0,
                          e->line, e->column};
        if (!ds.where) return out_of_memory(L);
        return params_validate(L->a, NULL, L->ecology->species_params, L->ecology->n_species_params,
                               &ds, &sp->ecology, L->err);
    }
    if (!L->ecology)
        return located(L->err, file, eco->key_line, eco->key_column,
                       "species '%s' has an '%s:' block, but the scene has no 'ecology:' section "
                       "to use it; add one (ecology: {plugin: ...}) or remove this block",
                       e->name, section);
    if (!L->ecology->species_section)
        return located(L->err, file, eco->key_line, eco->key_column,
                       "ecology plugin '%s' takes no per-species block; remove '%s:' from "
                       "species '%s'", L->sf->ecology.plugin, section, e->name);
    param_scope es = {file, e->dir, arena_printf(L->a, "species.%s.%s", e->name, section), NULL, 0,
                      eco->key_line, eco->key_column};
    if (!es.where) return out_of_memory(L);
    return params_validate(L->a, eco->value, L->ecology->species_params,
                           L->ecology->n_species_params, &es, &sp->ecology, L->err);
}

static int read_species(loader *L, const ynode *node)
{
    if (!node) return 0;
    if (collect_species(L, node, L->file, L->dir)) return -1;
    scene_file *sf = L->sf;
    sf->species = arena_alloc(L->a, (size_t)L->n_entries * sizeof *sf->species + 1);
    if (!sf->species) return out_of_memory(L);
    for (uint32_t i = 0; i < L->n_entries; i++) {
        if (read_species_entry(L, &L->entries[i], &sf->species[i])) return -1;
        sf->n_species = i + 1;
    }
    return 0;
}

/* --- plants and objects --------------------------------------------------------------------- */

static int expect_list(loader *L, const ynode *node, const char *section, const char *example)
{
    if (node->kind == YNODE_SEQUENCE) return 0;
    return located(L->err, L->file, node->line, node->column,
                   "'%s' must be a list (%s), got %s", section, example, ynode_kind_phrase(node));
}

static int read_plants(loader *L, const ynode *node)
{
    if (!node || ynode_is_null(node)) return 0;
    if (expect_list(L, node, "plants", "- {species: name, position: [x, y]}")) return -1;
    scene_file *sf = L->sf;
    sf->plants = arena_alloc(L->a, (size_t)node->n_items * sizeof *sf->plants + 1);
    const char **names = arena_alloc(L->a, ((size_t)sf->n_species + 1) * sizeof *names);
    if (!sf->plants || !names) return out_of_memory(L);
    for (uint32_t i = 0; i < sf->n_species; i++) names[i] = sf->species[i].name;
    for (uint32_t i = 0; i < node->n_items; i++) {
        const ynode *item = node->items[i];
        param_scope scope = {L->file, L->dir, arena_printf(L->a, "plants[%u]", i), NULL, 0,
                             item->line, item->column};
        const sylva_params *p;
        if (!scope.where) return out_of_memory(L);
        if (item->kind != YNODE_MAPPING)
            return located(L->err, L->file, item->line, item->column,
                           "'%s' must be a mapping (species: ..., position: ...), got %s",
                           scope.where, ynode_kind_phrase(item));
        if (params_validate(L->a, item, host_schema_plant.params, host_schema_plant.n_params,
                            &scope, &p, L->err))
            return -1;
        plant_spec *pl = &sf->plants[sf->n_plants];
        const sylva_value *species = sylva_param(p, "species"), *pos = sylva_param(p, "position");
        int index = scene_file_species_index(sf, species->s);
        if (index < 0)
            return unknown_name(L, L->file, species, "species", "species", scope.where, names,
                                sf->n_species);
        pl->species = (uint32_t)index;
        pl->position[0] = pos->list[0], pl->position[1] = pos->list[1];
        pl->position[2] = pos->len == 3 ? pos->list[2] : 0.0;
        pl->snap_to_terrain = pos->len == 2;
        pl->rotation_deg = sylva_param_real(p, "rotation");
        pl->scale = sylva_param_real(p, "scale");
        pl->age = sylva_param_real(p, "age");
        pl->line = item->line, pl->column = item->column;
        sf->n_plants++;
    }
    return 0;
}

static int read_objects(loader *L, const ynode *node)
{
    if (!node || ynode_is_null(node)) return 0;
    if (expect_list(L, node, "objects", "- {shape: box, size: [...], position: [...]}")) return -1;
    scene_file *sf = L->sf;
    sf->objects = arena_alloc(L->a, (size_t)node->n_items * sizeof *sf->objects + 1);
    if (!sf->objects) return out_of_memory(L);
    const sylva_param_spec *os = host_schema_object.params;
    for (uint32_t i = 0; i < node->n_items; i++) {
        const ynode *item = node->items[i];
        param_scope scope = {L->file, L->dir, arena_printf(L->a, "objects[%u]", i), NULL, 0,
                             item->line, item->column};
        if (!scope.where) return out_of_memory(L);
        if (item->kind != YNODE_MAPPING)
            return located(L->err, L->file, item->line, item->column,
                           "'%s' must be a mapping (shape: ..., position: ...), got %s",
                           scope.where, ynode_kind_phrase(item));
        const ynode *shape_node = ynode_get(item, "shape");
        if (!shape_node)
            return located(L->err, L->file, item->line, item->column,
                           "missing required key 'shape' in '%s' (mesh, box, sphere, quad or disk)",
                           scope.where);
        sylva_value kind;
        if (param_value_read(L->a, shape_node, host_key(&host_schema_object, "shape"), &scope,
                             &kind, L->err))
            return -1;
        const host_schema *shape = host_schema_shape((shape_kind)kind.i);
        const sylva_params *p, *sp;
        if (validate_shared(L, item, &scope, os, host_schema_object.n_params, shape->params,
                            shape->n_params, NULL, &p, &sp))
            return -1;
        object_spec *o = &sf->objects[sf->n_objects];
        const sylva_value *name = sylva_param(p, "name");
        o->name = name->is_set ? name->s : scope.where;
        if (read_shape(L, L->file, (shape_kind)kind.i, sp, item, &o->shape)) return -1;
        copy3(o->position, sylva_param(p, "position"));
        copy3(o->rotation_deg, sylva_param(p, "rotation"));
        copy3(o->scale, sylva_param(p, "scale"));
        if (material_ref(L, L->file, sylva_param(p, "material"), scope.where, &o->material))
            return -1;
        o->line = item->line, o->column = item->column;
        sf->n_objects++;
    }
    return 0;
}

/* --- image, camera, sun, sky ---------------------------------------------------------------- */

static int read_section(loader *L, const char *name, const host_schema *schema,
                        const sylva_params **out)
{
    const ynode_pair *pr = ynode_get_pair(L->root, name);
    param_scope scope = {L->file, L->dir, name, NULL, 0, pr ? pr->key_line : L->root->line,
                         pr ? pr->key_column : L->root->column};
    return params_validate(L->a, pr ? pr->value : NULL, schema->params, schema->n_params, &scope,
                           out, L->err);
}

static int read_image(loader *L)
{
    const sylva_params *p;
    if (read_section(L, "image", &host_schema_image, &p)) return -1;
    image_settings *im = &L->sf->image;
    im->width = (uint32_t)sylva_param_int(p, "width");
    im->height = (uint32_t)sylva_param_int(p, "height");
    im->spp = (uint32_t)sylva_param_int(p, "spp");
    im->seed = (uint64_t)sylva_param_int(p, "seed");
    im->max_depth = (uint32_t)sylva_param_int(p, "max_depth");
    im->exposure = sylva_param_real(p, "exposure");
    return 0;
}

/* Of two keys that exclude each other, the one given later in the file. */
static const sylva_value *later_of(const sylva_value *a, const sylva_value *b)
{
    if (a->line != b->line) return a->line > b->line ? a : b;
    return a->column > b->column ? a : b;
}

static int read_camera(loader *L)
{
    if (!ynode_get(L->root, "camera"))
        return located(L->err, L->file, L->root->line, L->root->column,
                       "missing required section 'camera' (at least camera: {position: [x, y, z], "
                       "look_at: [x, y, z]})");
    const sylva_params *p;
    if (read_section(L, "camera", &host_schema_camera, &p)) return -1;
    camera_settings *c = &L->sf->camera;
    const sylva_value *pos = sylva_param(p, "position"), *look = sylva_param(p, "look_at"),
                      *dir = sylva_param(p, "direction"), *up = sylva_param(p, "up"),
                      *fov = sylva_param(p, "fov"), *focal = sylva_param(p, "focal_length"),
                      *sensor = sylva_param(p, "sensor_width");
    if (look->is_set && dir->is_set) {
        const sylva_value *at = later_of(look, dir);
        return located(L->err, L->file, at->line, at->column,
                       "the camera takes 'look_at' or 'direction', not both");
    }
    if (fov->is_set && focal->is_set) {
        const sylva_value *at = later_of(fov, focal);
        return located(L->err, L->file, at->line, at->column,
                       "the camera takes 'fov' or 'focal_length' (with sensor_width), not both");
    }
    if (sensor->is_set && !focal->is_set)
        return located(L->err, L->file, sensor->line, sensor->column,
                       "'sensor_width' is used only with 'focal_length'; give focal_length too "
                       "or remove it");
    copy3(c->position, pos);
    copy3(c->up, up);
    c->has_look_at = look->is_set;
    const sylva_value *view = look->is_set ? look : dir;
    if (beyond_float(c->position))
        return located(L->err, L->file, pos->line, pos->column,
                       "the camera 'position' lies beyond single precision (+-%g m), where the "
                       "renderer cannot place it", (double)FLT_MAX);
    if (look->is_set) {
        copy3(c->look_at, look);
        if (beyond_float(c->look_at))
            return located(L->err, L->file, look->line, look->column,
                           "'look_at' lies beyond single precision (+-%g m), where the renderer "
                           "cannot aim; give a nearer point on the same line, or 'direction'",
                           (double)FLT_MAX);
        int same = 1;
        for (int k = 0; k < 3; k++) {
            c->direction[k] = c->look_at[k] - c->position[k];
            same &= (float)c->look_at[k] == (float)c->position[k];
        }
        if (same)
            return located(L->err, L->file, look->line, look->column,
                           "'look_at' must differ from the camera 'position' (in single "
                           "precision, as the renderer holds them)");
    } else {
        copy3(c->direction, dir);
    }
    if (normalize3(c->direction))
        return located(L->err, L->file, view->line, view->column,
                       look->is_set ? "the view from 'position' to 'look_at' has no usable "
                                      "direction; give a nearer 'look_at'"
                                    : "'direction' must not be zero");
    double u[3]; /* the unit up, for the check; c->up keeps the value given */
    copy3(u, up);
    if (normalize3(u))
        return located(L->err, L->file, up->line, up->column, "'up' must not be zero");
    double cr[3] = {c->direction[1] * u[2] - c->direction[2] * u[1],
                    c->direction[2] * u[0] - c->direction[0] * u[2],
                    c->direction[0] * u[1] - c->direction[1] * u[0]};
    if (length3(cr) < 1e-9) {
        const sylva_value *at = up->is_set ? up : view->is_set ? view : pos;
        return located(L->err, L->file, at->line, at->column,
                       "the viewing direction is parallel to 'up' [%g, %g, %g]; give another "
                       "'up' or turn the view",
                       c->up[0], c->up[1], c->up[2]);
    }
    c->sensor_width_mm = sensor->r;
    if (focal->is_set) {
        c->focal_length_mm = focal->r;
        c->fov_deg = 2.0 * atan(sensor->r / (2.0 * focal->r)) / DEG;
    } else {
        c->focal_length_mm = 0.0;
        c->fov_deg = fov->r;
    }
    return 0;
}

#define SUN_IRRADIANCE_MAX 1e6 /* sylva's unit: 1 is about 100 klx; 1e6 is beyond any sun */

static int read_sun(loader *L)
{
    const sylva_params *p;
    if (read_section(L, "sun", &host_schema_sun, &p)) return -1;
    sun_settings *s = &L->sf->sun;
    const sylva_value *az = sylva_param(p, "azimuth"), *el = sylva_param(p, "elevation"),
                      *dir = sylva_param(p, "direction");
    if (dir->is_set && (az->is_set || el->is_set)) {
        const sylva_value *at = later_of(dir, az->is_set ? az : el);
        return located(L->err, L->file, at->line, at->column,
                       "the sun takes 'direction' or 'azimuth'/'elevation', not both");
    }
    if (dir->is_set) {
        copy3(s->direction, dir);
        if (normalize3(s->direction))
            return located(L->err, L->file, dir->line, dir->column, "'direction' must not be zero");
        double azimuth = atan2(s->direction[0], s->direction[1]) / DEG;
        s->azimuth_deg = azimuth < 0.0 ? azimuth + 360.0 : azimuth;
        s->elevation_deg = asin(fmax(-1.0, fmin(1.0, s->direction[2]))) / DEG;
    } else {
        s->azimuth_deg = az->r, s->elevation_deg = el->r;
        double a = az->r * DEG, e = el->r * DEG;
        s->direction[0] = sin(a) * cos(e);
        s->direction[1] = cos(a) * cos(e);
        s->direction[2] = sin(e);
    }
    s->enabled = (int)sylva_param_int(p, "enabled");
    s->irradiance = sylva_param_real(p, "irradiance");
    copy3(s->color, sylva_param(p, "color"));
    double brightest = s->irradiance * fmax(s->color[0], fmax(s->color[1], s->color[2]));
    if (!(brightest <= SUN_IRRADIANCE_MAX)) {
        const sylva_value *irr = sylva_param(p, "irradiance"), *col = sylva_param(p, "color");
        const sylva_value *at = irr->is_set ? irr : col->is_set ? col : NULL;
        return located(L->err, L->file, at ? at->line : 1, at ? at->column : 1,
                       "the sun's irradiance times its colour reaches %g; it must stay at most "
                       "%g (1 is about 100 klx), or the image overflows to black",
                       brightest, SUN_IRRADIANCE_MAX);
    }
    s->angular_diameter_deg = sylva_param_real(p, "angular_diameter");
    return 0;
}

static int read_sky(loader *L)
{
    const sylva_params *p;
    if (read_section(L, "sky", &host_schema_sky, &p)) return -1;
    sky_settings *s = &L->sf->sky;
    const sylva_value *model = sylva_param(p, "model"), *color = sylva_param(p, "color"),
                      *turbidity = sylva_param(p, "turbidity");
    s->model = (sky_model)model->i;
    if (color->is_set && s->model != SKY_CONSTANT)
        return located(L->err, L->file, color->line, color->column,
                       "'color' applies to model: constant; this sky is '%s'", model->s);
    if (turbidity->is_set && s->model != SKY_PREETHAM)
        return located(L->err, L->file, turbidity->line, turbidity->column,
                       "'turbidity' applies to model: preetham; this sky is '%s'", model->s);
    s->turbidity = turbidity->r;
    s->scale = sylva_param_real(p, "scale");
    copy3(s->color, color);
    s->ground_albedo = sylva_param_real(p, "ground_albedo");
    copy3(s->ambient, sylva_param(p, "ambient"));
    return 0;
}

/* --- the file ------------------------------------------------------------------------------- */

static int check_sections(loader *L)
{
    uint32_t n = 0;
    while (host_sections[n]) n++;
    for (uint32_t i = 0; i < L->root->n_pairs; i++) {
        const ynode_pair *pr = &L->root->pairs[i];
        uint32_t k = 0;
        while (k < n && strcmp(host_sections[k], pr->key)) k++;
        if (k < n) continue;
        const char *near = param_nearest_name(pr->key, host_sections, n);
        if (near)
            return located(L->err, L->file, pr->key_line, pr->key_column,
                           "unknown section '%s'; did you mean '%s'?", pr->key, near);
        char list[512];
        name_list(host_sections, n, list, sizeof list);
        return located(L->err, L->file, pr->key_line, pr->key_column,
                       "unknown section '%s'; sections are %s", pr->key, list);
    }
    return 0;
}

static int load(loader *L, const char *path)
{
    scene_file *sf = L->sf;
    char *real = realpath(path, NULL); /* malloc'ed; copied and freed here */
    if (!real) return err_set(L->err, "%s: cannot open: %s", path, strerror(errno));
    const char *canon = arena_strdup(L->a, real);
    free(real);
    if (!canon || !(sf->dir = folder_of(L->a, canon))) return out_of_memory(L);
    L->dir = sf->dir;

    yaml_doc doc;
    if (yaml_doc_load(L->a, path, path, &doc, L->err)) return -1;
    L->file = doc.file;
    if (!doc.root)
        return located(L->err, L->file, 1, 1,
                       "the scene file is empty; it needs at least a 'camera:' section with a "
                       "'position'");
    if (doc.root->kind != YNODE_MAPPING)
        return located(L->err, L->file, doc.root->line, doc.root->column,
                       "a scene file must be a mapping of sections (image:, camera:, terrain:, "
                       "...), got %s", ynode_kind_phrase(doc.root));
    L->root = doc.root;
    L->chain[0] = (included_file){canon, L->file, 0, 0, NULL};
    L->chain_len = 1;

    if (check_sections(L) || read_image(L) || read_camera(L) || read_sun(L) || read_sky(L) ||
        read_materials(L, ynode_get(L->root, "materials")))
        return -1;
    const ynode_pair *eco = ynode_get_pair(L->root, "ecology");
    const ynode_pair *ter = ynode_get_pair(L->root, "terrain");
    if (read_ecology(L, eco ? eco->value : NULL, eco ? eco->key_line : 0,
                     eco ? eco->key_column : 0) ||
        read_terrain(L, ter ? ter->value : NULL, ter ? ter->key_line : 0,
                     ter ? ter->key_column : 0) ||
        read_species(L, ynode_get(L->root, "species")) ||
        read_plants(L, ynode_get(L->root, "plants")) ||
        read_objects(L, ynode_get(L->root, "objects")))
        return -1;
    if (scene_estimate_check(L->sf, L->err)) return -1; /* before any mesh is built */
    if (L->sf->ecology.plugin && L->sf->terrain.source == TERRAIN_NONE)
        return located(L->err, L->file, L->sf->ecology.line, L->sf->ecology.column,
                       "the ecology plugin '%s' places plants on the terrain, but the scene has no "
                       "'terrain:' section; add one (grid: ... or plugin: ...)", L->sf->ecology.plugin);
    return 0;
}

scene_file *scene_file_load(const char *path, const struct plugin_registry *plugins, err_buf *err)
{
    err_clear(err);
    if (!path || !path[0]) {
        err_set(err, "no scene file was named");
        return NULL;
    }
    arena *a = arena_new();
    scene_file *sf = a ? arena_alloc(a, sizeof *sf) : NULL;
    if (!sf || !(sf->path = arena_strdup(a, path))) {
        arena_free(a);
        err_set(err, "%s: out of memory while loading", path);
        return NULL;
    }
    sf->arena = a;
    loader L = {.a = a, .reg = plugins, .err = err, .sf = sf, .file = path};
    if (load(&L, path)) {
        arena_free(a);
        return NULL;
    }
    return sf;
}

void scene_file_free(scene_file *sf)
{
    if (sf) arena_free(sf->arena); /* sf itself lives in its arena */
}
