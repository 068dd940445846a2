/* scene_file_planting.c — the planting: section, a planting plan as the designer draws it:
 * woodland blocks (polygons), hedgerows and belts (lines), single trees (points) and fellings
 * (polygons), each with its species, spacing and nursery stock, and the year it is planted;
 * written in the scene file or drawn in a vector file (site/planting_ogr.h).
 * Each fault is refused at its key: an unknown species, a polygon that crosses itself, a
 * spacing or density of 0 (the schema's range), a key that does not belong to the feature's kind. The plants
 * are laid out and grown when the scene is built (scene_build/scene_planting.c); the plan's
 * place on the terrain is checked there. */
#include "scene_file/scene_file_loader.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene_file/scene_file.h"
#include "site/planting_ogr.h"

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

/* The form of a stock given by its height alone: the trade's size it is nearest (a whip up to
 * 1.35 m, a feathered tree up to 2.45 m, a standard above). */
static planting_stock_form form_of_height(double h)
{
    return h <= 1.35 ? STOCK_WHIP : h <= 2.45 ? STOCK_FEATHERED : STOCK_STANDARD;
}

/* The nursery stock: the trade's size, or a height. */
static void read_stock(const sylva_params *p, planting_feature *f)
{
    const sylva_value *height = sylva_param(p, "stock_height"), *size = sylva_param(p, "stock");
    f->stock = (planting_stock_form)size->i;
    if (height->is_set) {
        f->stock_height[0] = f->stock_height[1] = height->r;
        if (!size->is_set) f->stock = form_of_height(height->r);
    } else {
        memcpy(f->stock_height, stock_heights[size->i], sizeof f->stock_height);
    }
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

/* A number attribute of a file's feature (NAN when absent), checked to lie in (lo, hi]. */
static int file_number(loader *L, const sylva_value *file, const char *where, const plan_shape *sh, int field,
                       double lo, double hi, double *out)
{
    const char *text = sh->value[field];
    *out = NAN;
    if (!text) return 0;
    char *end;
    double v = strtod(text, &end);
    if (end == text || *end || !(v > lo && v <= hi))
        return sf_located(L->err, L->file, file->line, file->column, "planting: %s: '%s' is '%s'; give a number in "
                          "(%g, %g]", where, plan_field_names[field], text, lo, hi);
    *out = v;
    return 0;
}

/* A file feature's species, shares, spacing, rows and stock, from its attributes. */
static int read_file_attributes(loader *L, const sylva_value *file, const char *where, const plan_shape *sh,
                                planting_feature *f)
{
    if (f->kind == PLANTING_FELLING) return 0;
    sylva_value species = {.s = sh->value[PLAN_SPECIES], .line = file->line, .column = file->column};
    if (!species.s)
        return sf_located(L->err, L->file, file->line, file->column, "planting: %s has no 'species' attribute; "
                          "give the scene's species, separated by spaces", where);
    if (read_species(L, &species, where, f)) return -1;
    if (f->kind == PLANTING_TREE && f->n_species != 1)
        return sf_located(L->err, L->file, file->line, file->column, "planting: %s: a tree is of one species; '%s' "
                          "names %u", where, species.s, f->n_species);
    const char *shares = sh->value[PLAN_SHARES];
    double sum = 0;
    for (uint32_t i = 0; i < f->n_species; i++) {
        char *end = NULL;
        f->share[i] = shares ? strtod(shares, &end) : 1.0;
        if (shares && (end == shares || !(f->share[i] > 0)))
            return sf_located(L->err, L->file, file->line, file->column, "planting: %s: 'shares' is '%s'; give one "
                              "share above 0 per species, separated by spaces", where, sh->value[PLAN_SHARES]);
        if (shares) shares = end;
        sum += f->share[i];
    }
    for (uint32_t i = 0; i < f->n_species; i++) f->share[i] /= sum;
    double spacing, density, rows, row_spacing, stock_height;
    if (file_number(L, file, where, sh, PLAN_SPACING, 0, 1000, &spacing) ||
        file_number(L, file, where, sh, PLAN_DENSITY, 0, 100000, &density) ||
        file_number(L, file, where, sh, PLAN_ROWS, 0, 50, &rows) ||
        file_number(L, file, where, sh, PLAN_ROW_SPACING, 0, 100, &row_spacing) ||
        file_number(L, file, where, sh, PLAN_STOCK_HEIGHT, 0, 30, &stock_height))
        return -1;
    f->spacing = !isnan(density) ? sqrt(10000.0 / density) : !isnan(spacing) ? spacing : 2.0;
    f->rows = isnan(rows) ? 1 : (uint32_t)rows;
    f->row_spacing = isnan(row_spacing) ? 1.5 : row_spacing;
    int stock = 0;
    const char *size = sh->value[PLAN_STOCK];
    while (size && host_stock_sizes[stock] && strcmp(host_stock_sizes[stock], size)) stock++;
    if (size && !host_stock_sizes[stock])
        return sf_located(L->err, L->file, file->line, file->column, "planting: %s: 'stock' is '%s'; give whip, "
                          "feathered or standard, or a stock_height", where, size);
    f->stock = (planting_stock_form)stock;
    if (!isnan(stock_height)) f->stock_height[0] = f->stock_height[1] = stock_height;
    else memcpy(f->stock_height, stock_heights[stock], sizeof f->stock_height);
    if (!isnan(stock_height) && !size) f->stock = form_of_height(stock_height);
    return 0;
}

/* One feature of the plan's file into f: its kind from its geometry (and kind attribute). */
static int read_file_feature(loader *L, const sylva_value *file, const char *shown, const plan_shape *sh,
                             planting_feature *f)
{
    const char *where = sf_arena_printf(L->a, "%s %s", shown, sh->feature);
    if (!where) return sf_out_of_memory(L);
    int felling = sh->value[PLAN_KIND] && !strcmp(sh->value[PLAN_KIND], "felling");
    static const planting_kind by_geometry[] = {PLANTING_TREE, PLANTING_BELT, PLANTING_BLOCK};
    *f = (planting_feature){.kind = felling ? PLANTING_FELLING : by_geometry[sh->geometry], .file = L->file,
                            .line = file->line, .column = file->column, .rows = 1,
                            .name = sh->value[PLAN_NAME] ? sh->value[PLAN_NAME] : where, .xy = sh->xy, .n_xy = sh->n_xy};
    if (felling && sh->geometry != PLAN_POLYGON)
        return sf_located(L->err, L->file, file->line, file->column, "planting: %s: a felling is a polygon", where);
    for (uint32_t k = 0; k < f->n_xy; k++)
        f->xy[k][0] -= L->sf->site.origin[0], f->xy[k][1] -= L->sf->site.origin[1];
    uint32_t a = 0, b = 0;
    if (sh->geometry == PLAN_POLYGON && (f->n_xy < 3 || !ring_crossing((const double (*)[2])f->xy, f->n_xy, &a, &b)))
        return sf_located(L->err, L->file, file->line, file->column, f->n_xy < 3 ? "planting: %s: the polygon has "
                          "fewer than 3 corners" : "planting: %s: the polygon crosses itself: its edge from corner %u "
                          "meets its edge from corner %u; draw the outline once around, without crossing", where, a, b);
    if (sh->geometry == PLAN_LINE && f->n_xy < 2)
        return sf_located(L->err, L->file, file->line, file->column, "planting: %s: the line has one point", where);
    return read_file_attributes(L, file, where, sh, f);
}

/* The features of the plan's file (planting: {file: ...}), after the written ones. */
static int read_plan_file(loader *L, const sylva_params *p, const ynode *node, uint32_t n_written)
{
    const sylva_value *file = sylva_param(p, "file");
    const char *shown = ynode_get(node, "file")->text;
    if (!L->site)
        return sf_located(L->err, L->file, file->line, file->column, "'planting.file' is drawn in map coordinates, "
                          "but the scene has no 'site:' section; add one with the site's crs and origin");
    plan_shape *shapes;
    uint32_t n;
    err_buf why = {{0}};
    if (plan_read_ogr(L->a, file->s, shown, sylva_param(p, "layer")->s, sylva_param(p, "crs")->s,
                      L->sf->site.crs_wkt, &shapes, &n, &why))
        return sf_located(L->err, L->file, file->line, file->column, "planting: %s", why.msg);
    planting_spec *ps = &L->sf->planting;
    planting_feature *all = arena_alloc(L->a, ((size_t)n_written + n) * sizeof *all);
    if (!all) return sf_out_of_memory(L);
    if (n_written) memcpy(all, ps->features, (size_t)n_written * sizeof *all);
    ps->features = all;
    for (uint32_t i = 0; i < n; i++) {
        if (read_file_feature(L, file, shown, &shapes[i], &all[ps->n_features])) return -1;
        ps->n_plants_drawn += all[ps->n_features].kind != PLANTING_FELLING;
        ps->n_features++;
    }
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
    ps->ecology = (int)sylva_param_int(p, "ecology");
    ps->age_existing = (int)sylva_param_int(p, "age_existing");
    ps->maintenance_years = (uint32_t)sylva_param_int(p, "maintenance_years");
    ps->line = section->key_line, ps->column = section->key_column;
    uint32_t n = 0;
    for (int k = 0; k < PLANTING_KINDS; k++) n += sylva_param(p, kind_keys[k])->len;
    if (!n && !sylva_param(p, "file")->is_set)
        return sf_located(L->err, L->file, section->key_line, section->key_column, "'planting' plants nothing and "
                          "fells nothing; give file:, blocks:, belts:, trees: or felling:");
    if (!(ps->features = arena_alloc(L->a, (size_t)n * sizeof *ps->features + 1))) return sf_out_of_memory(L);
    for (int k = 0; k < PLANTING_KINDS; k++) {
        const sylva_value *list = sylva_param(p, kind_keys[k]);
        for (uint32_t i = 0; i < list->len; i++) {
            if (read_feature(L, &list->items[i], (planting_kind)k, i, &ps->features[ps->n_features])) return -1;
            ps->n_plants_drawn += k != PLANTING_FELLING;
            ps->n_features++;
        }
    }
    return sylva_param(p, "file")->is_set ? read_plan_file(L, p, node, ps->n_features) : 0;
}
