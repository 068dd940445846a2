/* scene_file_study.c — the study: section: which viewpoints `sylva study` renders (the scene's,
 * by name, and those of a points file, scene_file_points.c), the products and frames of each,
 * and their size in pixels (docs/study.md). Names are checked here, each fault at the name. */
#include "scene_file/scene_file_loader.h"

#include <string.h>

#include "util/name_list.h"

/* The keys read here rather than by the schema: a list of names or names in one string. */
static const char *const name_keys[] = {"viewpoints", "products", "frames"};
#define N_NAME_KEYS 3u

/* The names of one key, each with where it stands. */
typedef struct name_list {
    sylva_value *names;      /* .s the name, .line and .column where it stands */
    uint32_t n;
} name_list;

/* The names in the text of a scalar (spaces or commas between them) appended to out. */
static int split_scalar(loader *L, const ynode *node, name_list *out)
{
    const char *text = node->text, *name;
    for (size_t len; (len = name_list_next(&text, &name));) {
        sylva_value *v = &out->names[out->n++];
        *v = (sylva_value){.s = sf_arena_printf(L->a, "%.*s", (int)len, name), .line = node->line,
                           .column = node->column + (uint32_t)(name - node->text) + (node->quoted ? 1u : 0u)};
        if (!v->s) return sf_out_of_memory(L);
    }
    return 0;
}

/* The names of `key`: a sequence of names, or one scalar of names; an absent key gives the names
 * of its schema default (none for viewpoints). */
static int read_names(loader *L, const ynode *section, const char *key, name_list *out)
{
    const ynode_pair *pr = ynode_get_pair(section, key);
    const sylva_param_spec *spec = sf_host_key(&host_schema_study, key);
    ynode def = {.kind = YNODE_SCALAR, .text = spec->def_str ? spec->def_str : "", .line = L->sf->study.line,
                 .column = L->sf->study.column};
    const ynode *node = pr && !ynode_is_null(pr->value) ? pr->value : &def;
    uint32_t cap = node->kind == YNODE_SEQUENCE ? node->n_items : (uint32_t)strlen(node->text) / 2 + 1;
    *out = (name_list){.names = arena_alloc(L->a, (size_t)cap * sizeof *out->names + 1)};
    if (!out->names) return sf_out_of_memory(L);
    if (node->kind == YNODE_SCALAR) return split_scalar(L, node, out);
    if (node->kind == YNODE_SEQUENCE) {
        for (uint32_t i = 0; i < node->n_items; i++) {
            const ynode *item = node->items[i];
            if (item->kind != YNODE_SCALAR || !item->text[0])
                return sf_located(L->err, L->file, item->line, item->column,
                                  "'study.%s' lists names; item %u is %s", key, i + 1, ynode_kind_phrase(item));
            out->names[out->n++] = (sylva_value){.s = item->text, .line = item->line, .column = item->column};
        }
        return 0;
    }
    return sf_located(L->err, L->file, node->line, node->column,
                      "'study.%s' must be a list of names ([a, b]) or names separated by spaces or commas, got %s",
                      key, ynode_kind_phrase(node));
}

/* The bit mask of the names of `key` among `choices` (kind: "product", "frame"). */
static int read_choices(loader *L, const ynode *section, const char *key, const char *kind,
                        const char *const *choices, unsigned *mask)
{
    name_list l;
    if (read_names(L, section, key, &l)) return -1;
    uint32_t n = 0;
    while (choices[n]) n++;
    *mask = 0;
    for (uint32_t i = 0; i < l.n; i++) {
        uint32_t k = 0;
        while (k < n && strcmp(choices[k], l.names[i].s)) k++;
        if (k == n) return sf_unknown_name(L, L->file, &l.names[i], kind, key, "study", choices, n);
        *mask |= 1u << k;
    }
    if (!*mask)
        return sf_located(L->err, L->file, L->sf->study.line, L->sf->study.column,
                          "'study.%s' names none; give at least one of them", key);
    return 0;
}

/* The chosen viewpoints: each the name of one of the scene's viewpoints or of a point. */
static int read_viewpoint_names(loader *L, const ynode *section)
{
    scene_file *sf = L->sf;
    study_settings *st = &sf->study;
    name_list l;
    if (read_names(L, section, "viewpoints", &l)) return -1;
    uint32_t n = sf->n_viewpoints + st->n_points;
    const char **defined = arena_alloc(L->a, (size_t)n * sizeof *defined + 1);
    if (!defined || !(st->viewpoints = arena_alloc(L->a, (size_t)l.n * sizeof *st->viewpoints + 1)))
        return sf_out_of_memory(L);
    for (uint32_t i = 0; i < n; i++)
        defined[i] = i < sf->n_viewpoints ? sf->viewpoints[i].name : st->points[i - sf->n_viewpoints].name;
    for (uint32_t i = 0; i < l.n; i++) {
        uint32_t k = 0;
        while (k < n && strcmp(defined[k], l.names[i].s)) k++;
        if (k == n) return sf_unknown_name(L, L->file, &l.names[i], "viewpoint", "viewpoints", "study", defined, n);
        for (uint32_t j = 0; j < i; j++)
            if (!strcmp(l.names[j].s, l.names[i].s))
                return sf_located(L->err, L->file, l.names[i].line, l.names[i].column,
                                  "viewpoint '%s' is listed twice in 'study.viewpoints'", l.names[i].s);
        st->viewpoints[i] = l.names[i].s;
    }
    st->n_viewpoints = l.n;
    if (!l.n) st->viewpoints = NULL;
    return 0;
}

/* size, or print_width and dpi: one way of giving the frames' size. */
static int read_size(loader *L, const sylva_params *p)
{
    study_settings *st = &L->sf->study;
    const sylva_value *size = sylva_param(p, "size"), *print = sylva_param(p, "print_width");
    st->size[0] = (uint32_t)size->list[0], st->size[1] = (uint32_t)size->list[1];
    st->print_width_mm = print->r;
    st->dpi = sylva_param_real(p, "dpi");
    if (size->is_set && ((double)st->size[0] != size->list[0] || (double)st->size[1] != size->list[1] ||
                         !st->size[0]))
        return sf_located(L->err, L->file, size->line, size->column,
                          "'study.size' is [width, height] in whole pixels from 1 to %d, or [width, 0] for each "
                          "frame's own height, got [%g, %g]", HOST_IMAGE_MAX_SIZE, size->list[0], size->list[1]);
    if (size->is_set && print->is_set && print->r > 0)
        return sf_located(L->err, L->file, print->line, print->column,
                          "'study' takes size (pixels) or print_width (millimetres at dpi), not both");
    return 0;
}

int sf_read_study(loader *L)
{
    const ynode_pair *pr = ynode_get_pair(L->root, "study");
    study_settings *st = &L->sf->study;
    st->line = pr ? pr->key_line : L->root->line, st->column = pr ? pr->key_column : L->root->column;
    uint32_t n_keys;
    const sylva_param_spec *keys = sf_keys_without(L, &host_schema_study, name_keys, N_NAME_KEYS, &n_keys);
    if (!keys) return -1;
    param_scope scope = {L->file, L->dir, "study", name_keys, N_NAME_KEYS, st->line, st->column};
    const sylva_params *p;
    const ynode *section = pr && !ynode_is_null(pr->value) ? pr->value : NULL;
    if (params_validate(L->a, section, keys, n_keys, &scope, &p, L->err) || read_size(L, p)) return -1;
    st->eye_height = sylva_param_real(p, "eye_height");
    st->spp = (uint32_t)sylva_param(p, "spp")->i;
    st->inner_edges = (int)sylva_param_int(p, "inner_edges");
    st->points_layer = sylva_param(p, "points_layer")->s;
    const sylva_value *points = sylva_param(p, "points");
    if (points->is_set) {
        const ynode *written = ynode_get(section, "points");
        if (sf_read_points(L, points->s, written->text, st->points_layer, st->eye_height))
            return err_locate(L->err, L->file, points->line, points->column);
    }
    if (sf_read_study_years(L, sylva_param(p, "years"))) return -1;
    return read_choices(L, section, "products", "product", host_study_products, &st->products) ||
           read_choices(L, section, "frames", "frame", host_study_frames, &st->frames) ||
           read_viewpoint_names(L, section);
}
