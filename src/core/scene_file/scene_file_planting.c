/* scene_file_planting.c — the planting: section, a planting plan as the designer draws it:
 * woodland blocks (polygons), hedgerows and belts (lines), single trees (points) and fellings
 * (polygons), each with its species, spacing and nursery stock, and the year it is planted.
 * Each fault is refused at its key: an unknown species, a polygon that crosses itself, a
 * spacing or density of 0 (the schema's range), a key that does not belong to the feature's kind. The plants
 * are laid out and grown when the scene is built (scene_build/scene_planting.c); the plan's
 * place on the terrain is checked there. */
#include "scene_file/scene_file_loader.h"

#include <math.h>
#include <string.h>

#include "scene_file/scene_file.h"

/* The trade's heights of each stock size (host_stock_sizes order), metres. */
static const double stock_heights[][2] = {{0.6, 0.9}, {1.8, 2.4}, {2.5, 3.0}};

static const char *const kind_keys[PLANTING_KINDS] = {"blocks", "belts", "trees", "felling"};

/* The species names of v (spaces or commas between them) into f; unknown ones refused. */
static int read_species(loader *L, const sylva_value *v, const char *where, planting_feature *f)
{
    for (const char *p = v->s; *p;) {
        p += strspn(p, " ,\t");
        if (!*p) break;
        size_t len = strcspn(p, " ,\t");
        if (f->n_species == PLANTING_MAX_SPECIES)
            return sf_located(L->err, L->file, v->line, v->column, "%s names more than %u species; a block's mix "
                              "or a belt's sequence holds at most %u", where, PLANTING_MAX_SPECIES, PLANTING_MAX_SPECIES);
        sylva_value named = *v;
        if (!(named.s = sf_arena_printf(L->a, "%.*s", (int)len, p))) return sf_out_of_memory(L);
        int index = scene_file_species_index(L->sf, named.s);
        if (index < 0) {
            const char **names = arena_alloc(L->a, ((size_t)L->sf->n_species + 1) * sizeof *names);
            if (!names) return sf_out_of_memory(L);
            for (uint32_t i = 0; i < L->sf->n_species; i++) names[i] = L->sf->species[i].name;
            return sf_unknown_name(L, L->file, &named, "species", "species", where, names, L->sf->n_species);
        }
        f->species[f->n_species++] = (uint32_t)index;
        p += len;
    }
    return 0;
}

/* 1 when segments ab and cd cross or touch (collinear overlaps included). */
static int segments_meet(const double *a, const double *b, const double *c, const double *d)
{
    double d1 = (d[0] - c[0]) * (a[1] - c[1]) - (d[1] - c[1]) * (a[0] - c[0]);
    double d2 = (d[0] - c[0]) * (b[1] - c[1]) - (d[1] - c[1]) * (b[0] - c[0]);
    double d3 = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    double d4 = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2> 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return 1;
    if (d1 == 0 && d2 == 0 && d3 == 0 && d4 == 0)
        return fmax(a[0], b[0]) >= fmin(c[0], d[0]) && fmax(c[0], d[0]) >= fmin(a[0], b[0]) &&
               fmax(a[1], b[1]) >= fmin(c[1], d[1]) && fmax(c[1], d[1]) >= fmin(a[1], b[1]);
    return 0;
}

/* A ring's first pair of edges that are not neighbours and meet: 0 with *i, *j set, else -1. */
static int ring_crossing(const double (*xy)[2], uint32_t n, uint32_t *i_out, uint32_t *j_out)
{
    for (uint32_t i = 0; i < n; i++)
        for (uint32_t j = i + 2; j < n; j++) {
            if (i == 0 && j == n - 1) continue; /* the closing edge meets the first at corner 0 */
            if (segments_meet(xy[i], xy[(i + 1) % n], xy[j], xy[(j + 1) % n])) {
                *i_out = i, *j_out = j;
                return 0;
            }
        }
    return -1;
}

/* The feature's points from its polygon, line or position key, checked for its kind. */
static int read_points(loader *L, const sylva_params *p, const char *where, planting_feature *f)
{
    static const char *const shape_key[PLANTING_KINDS] = {"polygon", "line", "position", "polygon"};
    static const char *const shape_form[PLANTING_KINDS] = {"polygon: [[x, y], [x, y], [x, y], ...]",
                                                           "line: [[x, y], [x, y], ...]", "position: [x, y]",
                                                           "polygon: [[x, y], [x, y], [x, y], ...]"};
    for (int k = 0; k < PLANTING_KINDS; k++) {
        const sylva_value *v = sylva_param(p, shape_key[k]);
        if (v->is_set && strcmp(shape_key[k], shape_key[f->kind]))
            return sf_located(L->err, L->file, v->line, v->column, "%s: '%s' does not belong to %s; give %s",
                              where, shape_key[k], kind_keys[f->kind], shape_form[f->kind]);
    }
    const sylva_value *v = sylva_param(p, shape_key[f->kind]);
    if (!v->is_set)
        return sf_located(L->err, L->file, p->line, p->column, "%s needs its place: %s", where, shape_form[f->kind]);
    uint32_t n = f->kind == PLANTING_TREE ? 1 : v->rows, least = f->kind == PLANTING_BELT ? 2 : f->kind == PLANTING_TREE ? 1 : 3;
    if (f->kind != PLANTING_TREE && v->cols != 2)
        return sf_located(L->err, L->file, v->line, v->column, "%s: '%s' holds points of %u numbers; give %s",
                          where, shape_key[f->kind], v->cols, shape_form[f->kind]);
    if (n < least)
        return sf_located(L->err, L->file, v->line, v->column, "%s: '%s' has %u point%s; it needs at least %u",
                          where, shape_key[f->kind], n, n == 1 ? "" : "s", least);
    if (!(f->xy = arena_alloc(L->a, (size_t)n * sizeof *f->xy))) return sf_out_of_memory(L);
    const double *shift = L->sf->planting.map_coordinates ? L->sf->site.origin : (const double[2]){0, 0};
    for (uint32_t i = 0; i < n; i++)
        f->xy[i][0] = v->list[2 * i] - shift[0], f->xy[i][1] = v->list[2 * i + 1] - shift[1];
    f->n_xy = n;
    uint32_t a, b;
    if ((f->kind == PLANTING_BLOCK || f->kind == PLANTING_FELLING) && !ring_crossing((const double (*)[2])f->xy, n, &a, &b))
        return sf_located(L->err, L->file, v->line, v->column, "%s: the polygon crosses itself: its edge from corner "
                          "%u (%g, %g) meets its edge from corner %u (%g, %g); draw the outline once around, without "
                          "crossing", where, a, f->xy[a][0], f->xy[a][1], b, f->xy[b][0], f->xy[b][1]);
    return 0;
}

/* How far apart the plants stand: spacing (2 m unless given), or a block's density. */
static int read_spacing(loader *L, const sylva_params *p, const char *where, planting_feature *f)
{
    const sylva_value *spacing = sylva_param(p, "spacing"), *density = sylva_param(p, "density");
    if (density->is_set && f->kind != PLANTING_BLOCK)
        return sf_located(L->err, L->file, density->line, density->column, "%s: 'density' sets a block's grid; a "
                          "belt gives spacing (along a row) and row_spacing", where);
    if (spacing->is_set && density->is_set)
        return sf_located(L->err, L->file, density->line, density->column, "%s: give spacing or density, not both",
                          where);
    f->spacing = density->is_set ? sqrt(10000.0 / density->r) : spacing->r;
    return 0;
}

/* The species and their shares (blocks), the sequence (belts) or the one species (trees). */
static int read_mix(loader *L, const sylva_params *p, const char *where, planting_feature *f)
{
    const sylva_value *species = sylva_param(p, "species"), *shares = sylva_param(p, "shares");
    if (!species->is_set)
        return sf_located(L->err, L->file, p->line, p->column, "%s needs its species: species: \"oak birch\" names "
                          "the scene's species", where);
    if (read_species(L, species, where, f)) return -1;
    if (!f->n_species)
        return sf_located(L->err, L->file, species->line, species->column, "%s: 'species' names no species", where);
    if (f->kind == PLANTING_TREE && f->n_species != 1)
        return sf_located(L->err, L->file, species->line, species->column, "%s: a tree is of one species; '%s' "
                          "names %u", where, species->s, f->n_species);
    if (shares->is_set && f->kind != PLANTING_BLOCK)
        return sf_located(L->err, L->file, shares->line, shares->column, "%s: 'shares' mixes a block's species; a "
                          "belt repeats its species in the order given", where);
    if (shares->is_set && shares->len != f->n_species)
        return sf_located(L->err, L->file, shares->line, shares->column, "%s: 'shares' gives %u numbers for %u "
                          "species; give one share per species, in the order of species", where, shares->len,
                          f->n_species);
    double sum = 0;
    for (uint32_t i = 0; i < f->n_species; i++) sum += f->share[i] = shares->is_set ? shares->list[i] : 1.0;
    for (uint32_t i = 0; i < f->n_species; i++) f->share[i] /= sum;
    return 0;
}

/* The nursery stock: the trade's size, or a height. */
static void read_stock(const sylva_params *p, planting_feature *f)
{
    const sylva_value *height = sylva_param(p, "stock_height");
    if (height->is_set) f->stock_height[0] = f->stock_height[1] = height->r;
    else memcpy(f->stock_height, stock_heights[sylva_param(p, "stock")->i], sizeof f->stock_height);
}

/* Keys of the planting kinds that are not the feature's own (felling takes polygon and name). */
static int refuse_foreign_keys(loader *L, const sylva_params *p, const char *where, planting_kind kind)
{
    static const char *const planted_only[] = {"species", "spacing", "density", "stock", "stock_height"};
    static const char *const belt_only[] = {"rows", "row_spacing"};
    for (size_t k = 0; k < sizeof planted_only / sizeof *planted_only && kind == PLANTING_FELLING; k++) {
        const sylva_value *v = sylva_param(p, planted_only[k]);
        if (v->is_set)
            return sf_located(L->err, L->file, v->line, v->column, "%s: a felling removes what grows inside its "
                              "polygon and plants nothing; '%s' does not belong to it", where, planted_only[k]);
    }
    for (size_t k = 0; k < 2 && kind != PLANTING_BELT; k++) {
        const sylva_value *v = sylva_param(p, belt_only[k]);
        if (v->is_set)
            return sf_located(L->err, L->file, v->line, v->column, "%s: '%s' sets a belt's rows; it does not "
                              "belong to %s", where, belt_only[k], kind_keys[kind]);
    }
    const sylva_value *spacing = sylva_param(p, "spacing");
    if (kind == PLANTING_TREE && spacing->is_set)
        return sf_located(L->err, L->file, spacing->line, spacing->column, "%s: a single tree has no spacing",
                          where);
    return 0;
}

static int read_feature(loader *L, const sylva_params *p, planting_kind kind, uint32_t i, planting_feature *f)
{
    const char *where = sf_arena_printf(L->a, "planting.%s[%u]", kind_keys[kind], i);
    if (!where) return sf_out_of_memory(L);
    const sylva_value *name = sylva_param(p, "name");
    *f = (planting_feature){.kind = kind, .file = L->file, .line = p->line, .column = p->column, .rows = 1};
    f->name = name->is_set ? name->s : where + strlen("planting.");
    if (refuse_foreign_keys(L, p, where, kind) || read_points(L, p, where, f)) return -1;
    if (kind == PLANTING_FELLING) return 0;
    if (read_mix(L, p, where, f) || (kind != PLANTING_TREE && read_spacing(L, p, where, f))) return -1;
    read_stock(p, f);
    f->rows = (uint32_t)sylva_param(p, "rows")->i;
    f->row_spacing = sylva_param_real(p, "row_spacing");
    return 0;
}

int sf_read_planting(loader *L, const ynode_pair *section)
{
    if (!section || !section->value || ynode_is_null(section->value)) return 0;
    const ynode *node = section->value;
    if (node->kind != YNODE_MAPPING)
        return sf_located(L->err, L->file, node->line, node->column, "'planting' must be a mapping ({year: 2027, "
                          "belts: [...], blocks: [...], ...}), got %s", ynode_kind_phrase(node));
    param_scope scope = {L->file, L->dir, "planting", NULL, 0, section->key_line, section->key_column};
    const sylva_params *p;
    if (params_validate(L->a, node, host_schema_planting.params, host_schema_planting.n_params, &scope, &p, L->err))
        return -1;
    planting_spec *ps = &L->sf->planting;
    ps->year = sylva_param_real(p, "year");
    ps->map_coordinates = (int)sylva_param(p, "coordinates")->i;
    if (ps->map_coordinates && !L->site)
        return sf_located(L->err, L->file, sylva_param(p, "coordinates")->line, sylva_param(p, "coordinates")->column,
                          "'coordinates: map' gives the plan in the site's CRS, but the scene has no 'site:' "
                          "section; add one, or give local metres");
    ps->seed = (uint64_t)sylva_param(p, "seed")->i;
    ps->full_grown_age = sylva_param_real(p, "full_grown_age");
    ps->thinning_year = sylva_param_real(p, "thinning_year");
    ps->thinning_keep = sylva_param_real(p, "thinning_keep");
    ps->line = section->key_line, ps->column = section->key_column;
    uint32_t n = 0;
    for (int k = 0; k < PLANTING_KINDS; k++) n += sylva_param(p, kind_keys[k])->len;
    if (!n)
        return sf_located(L->err, L->file, section->key_line, section->key_column, "'planting' plants nothing and "
                          "fells nothing; give blocks:, belts:, trees: or felling:");
    if (!(ps->features = arena_alloc(L->a, (size_t)n * sizeof *ps->features))) return sf_out_of_memory(L);
    for (int k = 0; k < PLANTING_KINDS; k++) {
        const sylva_value *list = sylva_param(p, kind_keys[k]);
        for (uint32_t i = 0; i < list->len; i++) {
            if (read_feature(L, &list->items[i], (planting_kind)k, i, &ps->features[ps->n_features])) return -1;
            ps->n_plants_drawn += k != PLANTING_FELLING;
            ps->n_features++;
        }
    }
    return 0;
}
