/* scene_file_trees.c — the trees section: the existing trees of a survey file (site/tree_survey.h)
 * as tree_spec records in local metres, each of a scene species (by its species attribute mapped
 * through species_map, or a scene species' own name, else the default `species`) with a measured
 * height above 0, and optionally a crown diameter and an age. Every problem of a tree names its
 * feature (FID or CSV line) and stands at the key it is about; a loaded survey prints one line. */
#include "scene_file/scene_file.h"
#include "scene_file/scene_file_loader.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "site/tree_survey.h"

#define GOLDEN_ANGLE_DEG 137.50776405003785

/* The survey's species names mapped to scene species (species_map:). */
typedef struct species_map {
    const char **from;
    uint32_t *to;
    uint32_t n;
} species_map;

/* What the section says beyond the survey request, and what the load counts. */
typedef struct trees_reading {
    const sylva_params *p;
    const sylva_value *file;
    species_map map;
    int fallback;             /* the default species, or -1 */
    uint32_t *per_species;    /* trees of each scene species, by name or map */
    uint32_t defaulted;       /* trees given the default species */
    double full_grown_age;
} trees_reading;

static const char *const species_map_key[] = {"species_map"};

/* The scene's species names, for messages. */
static const char **species_names(loader *L)
{
    const scene_file *sf = L->sf;
    const char **names = arena_alloc(L->a, ((size_t)sf->n_species + 1) * sizeof *names);
    for (uint32_t i = 0; names && i < sf->n_species; i++) names[i] = sf->species[i].name;
    return names;
}

/* The scene species a key's value names; -1 with L->err set at the value. */
static int scene_species(loader *L, const sylva_value *v, const char *where)
{
    int index = scene_file_species_index(L->sf, v->s);
    if (index >= 0) return index;
    const char **names = species_names(L);
    if (!names) return sf_out_of_memory(L);
    sf_unknown_name(L, L->file, v, "species", "species", where, names, L->sf->n_species);
    return -1;
}

static int read_species_map(loader *L, const ynode *node, species_map *m)
{
    if (!node || ynode_is_null(node)) return 0;
    if (node->kind != YNODE_MAPPING)
        return sf_located(L->err, L->file, node->line, node->column,
                          "'trees.species_map' must be a mapping of the survey's names to the scene's species "
                          "({\"Pseudotsuga menziesii\": douglas_fir}), got %s", ynode_kind_phrase(node));
    m->from = arena_alloc(L->a, (size_t)node->n_pairs * sizeof *m->from + 1);
    m->to = arena_alloc(L->a, (size_t)node->n_pairs * sizeof *m->to + 1);
    if (!m->from || !m->to) return sf_out_of_memory(L);
    for (uint32_t i = 0; i < node->n_pairs; i++) {
        const ynode *v = node->pairs[i].value;
        if (!v || v->kind != YNODE_SCALAR)
            return sf_located(L->err, L->file, v ? v->line : node->line, v ? v->column : node->column,
                              "'trees.species_map' maps '%s' to %s; give a species name of the scene",
                              node->pairs[i].key, v ? ynode_kind_phrase(v) : "nothing");
        sylva_value name = {.is_set = 1, .s = v->text, .line = v->line, .column = v->column};
        int index = scene_species(L, &name, "trees.species_map");
        if (index < 0) return -1;
        m->from[m->n] = node->pairs[i].key, m->to[m->n++] = (uint32_t)index;
    }
    return 0;
}

/* The place of a key's value, or of `file` when the key was left to its default. */
static void key_place(const trees_reading *r, const char *key, uint32_t *line, uint32_t *column)
{
    const sylva_value *v = sylva_param(r->p, key);
    if (!v->is_set || !v->line) v = r->file;
    *line = v->line, *column = v->column;
}

static int refuse_at(loader *L, const trees_reading *r, const char *key, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static int refuse_at(loader *L, const trees_reading *r, const char *key, const char *fmt, ...)
{
    uint32_t line, column;
    key_place(r, key, &line, &column);
    char text[1536];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    return sf_located(L->err, L->file, line, column, "trees: %s", text);
}

/* The tree's scene species: mapped, a scene name, else the default; -1 with L->err set. */
static int tree_species(loader *L, trees_reading *r, const survey_point *pt, const char *shown)
{
    const char *name = pt->value[SURVEY_SPECIES];
    for (uint32_t i = 0; name && i < r->map.n; i++)
        if (!strcmp(r->map.from[i], name)) return r->per_species[r->map.to[i]]++, (int)r->map.to[i];
    int index = name ? scene_file_species_index(L->sf, name) : -1;
    if (index >= 0) return r->per_species[index]++, index;
    if (r->fallback >= 0) return r->defaulted++, r->fallback;
    char list[1024];
    const char **names = species_names(L);
    if (!names) return sf_out_of_memory(L);
    sf_name_list(names, L->sf->n_species, list, sizeof list);
    if (!name)
        return refuse_at(L, r, "species_field", "'%s' %s gives no species, and 'species:' names no default; give "
                         "one of the scene's species (%s)", shown, pt->feature, list);
    return refuse_at(L, r, "species_field", "'%s' %s: species '%s' is neither in species_map nor a species of the "
                     "scene (%s); map it (species_map: {\"%s\": ...}) or give a default with 'species:'", shown,
                     pt->feature, name, list, name);
}

/* A measured number of the tree (height, crown, age): *out > 0, or 0 when absent and optional. */
static int tree_measure(loader *L, const trees_reading *r, const survey_point *pt, const char *shown, int which,
                        const char *key, const char *what, int required, double *out)
{
    const char *text = pt->value[which];
    *out = 0;
    if (!text && !required) return 0;
    if (!text)
        return refuse_at(L, r, key, "'%s' %s has no %s; every surveyed tree needs its %s in metres, above 0",
                         shown, pt->feature, what, what);
    char *end;
    errno = 0;
    double v = strtod(text, &end);
    if (*end || errno || !isfinite(v))
        return refuse_at(L, r, key, "'%s' %s: %s '%s' is not a number; give it in metres", shown, pt->feature,
                         what, text);
    if (!(v > 0))
        return refuse_at(L, r, key, "'%s' %s: %s %g is not above 0; a surveyed tree's %s must be a length in "
                         "metres", shown, pt->feature, what, v, what);
    *out = v;
    return 0;
}

static int read_tree(loader *L, trees_reading *r, const survey_point *pt, const char *shown, uint32_t i,
                     tree_spec *t)
{
    int species = tree_species(L, r, pt, shown);
    if (species < 0) return -1;
    double years;
    if (tree_measure(L, r, pt, shown, SURVEY_HEIGHT, "height_field", "height", 1, &t->height) ||
        tree_measure(L, r, pt, shown, SURVEY_CROWN, "crown_field", "crown diameter", 0, &t->crown) ||
        tree_measure(L, r, pt, shown, SURVEY_AGE, "age_field", "age", 0, &years))
        return -1;
    t->species = (uint32_t)species;
    t->position[0] = pt->map[0] - L->sf->site.origin[0];
    t->position[1] = pt->map[1] - L->sf->site.origin[1];
    t->age = years > 0 ? fmin(1.0, years / r->full_grown_age) : 0.0;
    t->rotation_deg = fmod(GOLDEN_ANGLE_DEG * i, 360.0);
    t->feature = pt->feature;
    return 0;
}

/* The survey request of the section's keys. */
static void survey_request_of(const loader *L, const trees_reading *r, survey_request *rq)
{
    const sylva_params *p = r->p;
    *rq = (survey_request){.path = r->file->s, .layer = sylva_param(p, "layer")->s,
                           .crs = sylva_param(p, "crs")->s, .x_field = sylva_param(p, "x_field")->s,
                           .y_field = sylva_param(p, "y_field")->s, .site_wkt = L->sf->site.crs_wkt};
    const char *slash = strrchr(r->file->s, '/');
    rq->shown = slash ? slash + 1 : r->file->s;
    rq->field[SURVEY_SPECIES] = sylva_param(p, "species_field")->s;
    rq->field[SURVEY_HEIGHT] = sylva_param(p, "height_field")->s;
    rq->field[SURVEY_CROWN] = sylva_param(p, "crown_field")->s;
    rq->field[SURVEY_AGE] = sylva_param(p, "age_field")->s;
}

static int read_survey(loader *L, trees_reading *r, const survey_request *rq, survey_points *pts)
{
    static const char *const key_names[SURVEY_KEY_COUNT] = {"file", "layer", "crs", "x_field", "y_field",
                                                            "species_field", "height_field", "crown_field",
                                                            "age_field"};
    survey_key bad = SURVEY_KEY_FILE;
    err_buf why = {{0}};
    if (!survey_read(L->a, rq, pts, &bad, &why)) return 0;
    if (why.status == ERR_NOMEM) return sf_out_of_memory(L);
    return refuse_at(L, r, key_names[bad], "%s", why.msg);
}

/* n with thousands separated by commas ("1,115"). */
static const char *grouped(char buf[32], uint32_t n)
{
    char digits[16];
    int len = snprintf(digits, sizeof digits, "%u", n), o = 0;
    for (int i = 0; i < len; i++) {
        if (i && (len - i) % 3 == 0) buf[o++] = ',';
        buf[o++] = digits[i];
    }
    buf[o] = 0;
    return buf;
}

/* trees: 1,115 from ttops.gpkg (species: 1,115 default 'fir'), heights 1.5–26.9 m */
static void report(const loader *L, const trees_reading *r, const survey_request *rq)
{
    const trees_spec *ts = &L->sf->trees;
    char a[32], b[32], line[1024];
    int used = snprintf(line, sizeof line, "trees: %s from %s (species:", grouped(a, ts->n_trees), rq->shown);
    const char *sep = " ";
    for (uint32_t s = 0; s < L->sf->n_species && used < (int)sizeof line; s++)
        if (r->per_species[s])
            used += snprintf(line + used, sizeof line - used, "%s%s %s", sep, grouped(b, r->per_species[s]),
                             L->sf->species[s].name), sep = ", ";
    if (r->defaulted && used < (int)sizeof line)
        snprintf(line + used, sizeof line - used, "%s%s default '%s'", sep, grouped(b, r->defaulted),
                 L->sf->species[r->fallback].name);
    double lo = INFINITY, hi = -INFINITY;
    for (uint32_t i = 0; i < ts->n_trees; i++) lo = fmin(lo, ts->trees[i].height), hi = fmax(hi, ts->trees[i].height);
    if (ts->n_trees) fprintf(stderr, "%s), heights %.1f\u2013%.1f m\n", line, lo, hi);
    else fprintf(stderr, "%s none)\n", line);
}

static int read_trees(loader *L, trees_reading *r, const survey_request *rq)
{
    survey_points pts;
    if (read_survey(L, r, rq, &pts)) return -1;
    trees_spec *ts = &L->sf->trees;
    ts->trees = arena_alloc(L->a, (size_t)pts.n * sizeof *ts->trees + 1);
    r->per_species = arena_alloc(L->a, ((size_t)L->sf->n_species + 1) * sizeof *r->per_species);
    if (!ts->trees || !r->per_species) return sf_out_of_memory(L);
    for (uint32_t i = 0; i < pts.n; i++)
        if (read_tree(L, r, &pts.points[i], rq->shown, i, &ts->trees[ts->n_trees++])) return -1;
    if (!(L->flags & SCENE_FILE_QUIET)) report(L, r, rq);
    return 0;
}

int sf_read_trees(loader *L, const ynode_pair *section)
{
    if (!section || !section->value || ynode_is_null(section->value)) return 0;
    const ynode *node = section->value;
    if (node->kind != YNODE_MAPPING)
        return sf_located(L->err, L->file, node->line, node->column,
                          "'trees' must be a mapping ({file: survey.gpkg, species: name, ...}), got %s",
                          ynode_kind_phrase(node));
    param_scope scope = {L->file, L->dir, "trees", species_map_key, 1, section->key_line, section->key_column};
    uint32_t n_keys;
    const sylva_param_spec *keys = sf_keys_without(L, &host_schema_trees, species_map_key, 1, &n_keys);
    trees_reading r = {.fallback = -1};
    if (!keys || params_validate(L->a, node, keys, n_keys, &scope, &r.p, L->err)) return -1;
    r.file = sylva_param(r.p, "file");
    r.full_grown_age = sylva_param_real(r.p, "full_grown_age");
    if (!L->site)
        return sf_located(L->err, L->file, section->key_line, section->key_column,
                          "'trees' places a survey's map coordinates, but the scene has no 'site:' section; add "
                          "one with the site's crs and origin");
    const sylva_value *fallback = sylva_param(r.p, "species");
    if ((fallback->is_set && (r.fallback = scene_species(L, fallback, "trees")) < 0) ||
        read_species_map(L, ynode_get(node, "species_map"), &r.map))
        return -1;
    trees_spec *ts = &L->sf->trees;
    ts->file = ynode_get(node, "file")->text, ts->line = r.file->line, ts->column = r.file->column;
    ts->development = (int)sylva_param(r.p, "development")->i;
    survey_request rq;
    survey_request_of(L, &r, &rq);
    return read_trees(L, &r, &rq);
}
