/* wp_config.c — the plugin's block read into a wp_config (wp_config.h): the species from its file
 * and name, the `model` keys over it, the checks the schema cannot make, and the look. */
#include "wp_config.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "tree_look.h"
#include "wp_schema.h"
#include "wp_species_read.h"

/* "a, b, c" of the list's names, cut with "..." to fit n bytes. */
static void species_names(const wp_species_list *l, char *out, size_t n)
{
    size_t len = 0;
    out[0] = '\0';
    for (size_t i = 0; i < l->count; i++) {
        int w = snprintf(out + len, n - len, "%s'%s'", i ? ", " : "", l->items[i].species);
        if (w < 0 || (size_t)w >= n - len) {
            if (n > 4) snprintf(out + (len < n - 4 ? len : n - 4), 4, "...");
            return;
        }
        len += (size_t)w;
    }
}

/* The species of the file at `path` that `name` picks (NULL: the file's only one). */
static int species_from_file(plugin_params *r, const char *path, const char *name, wp_params *out,
                             plugin_err *err)
{
    wp_species_list list = {0}; /* owned here */
    plugin_err read = {0};
    if (wp_species_read_file(path, &list, &read))
        return plugin_fail_key(err, read.status, r->block, "file", "%s", read.msg);
    char names[600];
    species_names(&list, names, sizeof names);
    const wp_params *pick = NULL;
    int rc = SYLVA_OK;
    if (name && !(pick = wp_species_find(&list, name)))
        rc = plugin_fail_param(err, r->block, "name", "species '%s' is not in %s, which holds %s; give one of these",
                               name, path, names);
    else if (!name && list.count != 1)
        rc = list.count ? plugin_fail_param(err, r->block, "file", "%s holds %zu species (%s); choose one with name",
                                            path, list.count, names)
                        : plugin_fail_param(err, r->block, "file", "%s holds no species", path);
    else *out = pick ? *pick : list.items[0];
    wp_species_list_free(&list);
    return rc;
}

/* Member i of `model`, given as v, written into p. */
static int set_member(plugin_params *m, size_t i, const sylva_value *v, wp_params *p, plugin_err *err)
{
    const char *key = wp_model_schema[i].name;
    const wp_param_def *d = wp_param_find(wp_model_arbaro[i]);
    if (!d) return plugin_fail(err, SYLVA_ERR_INTERNAL, "model.%s names no row of the parameter table", key);
    if (d->type == WP_TEXT) {
        if (strlen(v->s) >= d->text_size)
            return plugin_fail_param(err, m->block, key, "model.%s is %zu bytes long; give at most %zu", key,
                                     strlen(v->s), d->text_size - 1);
        snprintf(wp_param_slot(d, p, 0), d->text_size, "%s", v->s);
        return SYLVA_OK;
    }
    if (!d->per_level) {
        if (d->type == WP_INT) *(int *)wp_param_slot(d, p, 0) = (int)v->i;
        else *(double *)wp_param_slot(d, p, 0) = v->r;
        return SYLVA_OK;
    }
    for (uint32_t l = 0; l < v->len && l < WP_LEVELS; l++) {
        double x = v->list[l];
        if (d->type == WP_INT) {
            if (x != floor(x))
                return plugin_fail_param(err, m->block, key, "model.%s gives %g at level %u; %s takes whole numbers",
                                         key, x, l, key);
            *(int *)wp_param_slot(d, p, (int)l) = (int)x;
        } else {
            *(double *)wp_param_slot(d, p, (int)l) = x;
        }
    }
    return SYLVA_OK;
}

/* "in [lo, hi]", "at least lo" or "at most hi" for row d's range. */
static void range_text(const wp_param_def *d, char *out, size_t n)
{
    if (isfinite(d->min) && isfinite(d->max)) snprintf(out, n, "in [%g, %g]", d->min, d->max);
    else if (isfinite(d->min)) snprintf(out, n, "at least %g", d->min);
    else snprintf(out, n, "at most %g", d->max);
}

/* The member of `model` that sets row d, or -1. */
static int member_of(const wp_param_def *d)
{
    for (size_t i = 0; i < WP_MODEL_SCHEMA_COUNT; i++)
        if (!strcmp(wp_model_arbaro[i], d->name)) return (int)i;
    return -1;
}

/* Every per-level value the tree reads lies in its row's range; a value out of it is reported at
 * the model member that gave it, else at model.levels (which made the level grow), else at the
 * key the species came from. */
static int check_levels(plugin_params *m, const wp_config *c, const char *file, plugin_err *err)
{
    wp_params p = c->species;
    if (p.levels > WP_LEVELS) {
        int given = plugin_param_given(m, "levels");
        return plugin_fail_param(err, given ? m->block : c->where, given ? "levels" : c->where_key,
                                 "Levels is %d; Arbaro 1.9 grows at most %d stem levels (give Levels 0 to %d)",
                                 p.levels, WP_LEVELS, WP_LEVELS);
    }
    for (size_t k = 0; k < wp_param_count; k++) {
        const wp_param_def *d = &wp_param_table[k];
        if (!d->per_level) continue;
        for (int l = 0; l < WP_LEVELS; l++) {
            if (!wp_param_used(d, p.levels, l)) continue;
            void *slot = wp_param_slot(d, &p, l);
            double x = d->type == WP_INT ? *(int *)slot : *(double *)slot;
            if (x >= d->min && x <= d->max) continue;
            int i = member_of(d);
            char range[64];
            range_text(d, range, sizeof range);
            const char *key = i >= 0 ? wp_model_schema[i].name : d->name;
            const sylva_value *v = i >= 0 ? plugin_param(m, key) : NULL;
            if (m->status) return m->status;
            if (v && v->is_set && (uint32_t)l < v->len)
                return plugin_fail_param(err, m->block, key, "model.%s gives %g at level %d, a level the tree grows; "
                                         "it must be %s there", key, x, l, range);
            if (plugin_param_given(m, "levels"))
                return plugin_fail_param(err, m->block, "levels", "model.levels %d grows level %d, where %s's %s is %g; "
                                         "give model.%s a value %s for level %d", p.levels, l,
                                         file ? file : "the default", d->name, x, key, range, l);
            return plugin_fail_param(err, c->where, c->where_key, "%s at level %d is %g; it must be %s",
                                     d->name, l, x, range);
        }
    }
    return m->status;
}

static int read_species(plugin_params *r, wp_config *c, plugin_err *err)
{
    const char *file = plugin_param_str(r, "file");
    const char *name = plugin_param_str(r, "name");
    const sylva_value *model = plugin_param(r, "model");
    c->seed = plugin_param_int(r, "seed");
    if (r->status) return r->status;
    c->where = r->block;
    c->where_key = model->is_set ? "model" : "file";
    c->model = model->is_set ? model->group : NULL;
    if (!file && !model->is_set)
        return plugin_fail_param(err, r->block, "file", "the species is missing; give file (an Arbaro species file "
                                 "or Helios' WeberPennTreeLibrary.xml, with name when it holds several), model "
                                 "(the Weber-Penn parameters inline), or both");
    if (name && !file)
        return plugin_fail_param(err, r->block, "name", "name picks a species of file, and no file is given; give "
                                 "file, or remove name and give the species in model");
    int rc = SYLVA_OK;
    if (file) rc = species_from_file(r, file, name, &c->species, err);
    else {
        wp_params_defaults(&c->species);
        snprintf(c->species.species, sizeof c->species.species, "inline"); /* named so in the grower's sentences */
    }
    if (rc) return rc;
    plugin_params m = plugin_params_in(r, model->group);
    for (size_t i = 0; i < WP_MODEL_SCHEMA_COUNT && !rc; i++) {
        const sylva_value *v = plugin_param(&m, wp_model_schema[i].name);
        if (m.status) return m.status;
        if (v->is_set) rc = set_member(&m, i, v, &c->species, err);
    }
    return rc ? rc : check_levels(&m, c, file, err);
}

/* Whether text names something (starts with a letter) rather than giving maps. */
static int is_a_name(const char *text)
{
    while (*text == ' ' || *text == '\t' || *text == '\n') text++;
    return (*text >= 'a' && *text <= 'z') || (*text >= 'A' && *text <= 'Z');
}

static int read_leaf(plugin_params *r, wp_config *c, plugin_err *err)
{
    const char *leaf = plugin_param_str(r, "leaf");
    if (r->status) return r->status;
    if (!leaf || !strcmp(leaf, "own")) {
        c->leaf = WP_LEAF_OWN;
        return SYLVA_OK;
    }
    int preset = 0;
    while (leaf_affine_preset_name((leaf_affine_preset)preset) &&
           strcmp(leaf, leaf_affine_preset_name((leaf_affine_preset)preset)))
        preset++;
    if (is_a_name(leaf) && !leaf_affine_preset_name((leaf_affine_preset)preset))
        return plugin_fail_param(err, r->block, "leaf", "'%.40s' is not a leaf; give own (the species' LeafShape), a "
                                 "preset (beech, maple, spruce, shrub, willow) or affine maps \"a b c d e f[ p]; ...\"",
                                 leaf);
    char why[PLUGIN_ERR_MAX - 64];
    if (tree_look_leaf(leaf, WP_LEAF_TEXTURE_SIZE, &c->leaf_maps, why, sizeof why) < 0)
        return plugin_fail_param(err, r->block, "leaf", "%s", why);
    c->leaf = WP_LEAF_CARD;
    return SYLVA_OK;
}

static void vec3(plugin_params *r, const char *name, double out[3])
{
    const sylva_value *v = plugin_param(r, name);
    for (int k = 0; k < 3; k++) out[k] = v->list[k];
}

static int read_look(plugin_params *r, wp_config *c, plugin_err *err)
{
    int rc = read_leaf(r, c, err);
    if (rc) return rc;
    vec3(r, "leaf_color", c->leaf_color);
    vec3(r, "leaf_transmittance", c->leaf_transmittance);
    vec3(r, "bark_color", c->bark_color);
    int bark = (int)plugin_param_int(r, "bark");
    const sylva_value *angle = plugin_param(r, "bark_angle");
    if (r->status) return r->status;
    char why[PLUGIN_ERR_MAX - 64];
    if (tree_look_leaf_balance(c->leaf_color, c->leaf_transmittance, why, sizeof why))
        return plugin_fail_param(err, r->block, "leaf_transmittance", "%s", why);
    if (tree_look_bark(bark, angle->is_set ? angle->r : NAN, &c->bark, why, sizeof why))
        return plugin_fail_param(err, r->block, angle->is_set ? "bark_angle" : "bark", "%s", why);
    return SYLVA_OK;
}

int wp_config_read(plugin_params *r, wp_config *cfg, plugin_err *err)
{
    memset(cfg, 0, sizeof *cfg);
    int rc = read_species(r, cfg, err);
    return rc ? rc : read_look(r, cfg, err);
}
