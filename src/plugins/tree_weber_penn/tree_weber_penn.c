/* tree_weber_penn.c — the plugin file: the descriptor and its operations — the species, the leaf
 * form, the model's caps and the materials in create(), one age variant per generate() (the
 * species at its age, wp_model_grow, the mesh, one mesh_append, the figures), and destroy().
 * The only file of the plugin that calls the host: the model reports failures in a plugin_err,
 * which plugin_report() hands to api->error or api->param_error. wp_entry.c exports the
 * descriptor. */
#include "tree_weber_penn.h"

#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plugin_host.h"
#include "sylva/tree_stats.h"
#include "leaf_affine.h"
#include "wp_age.h"
#include "wp_config.h"
#include "wp_leaf_form.h"
#include "wp_leaf_shape.h"
#include "wp_limits.h"
#include "wp_host_mesh.h"
#include "wp_model.h"
#include "wp_schema.h"
#include "wp_stats.h"

/* What create() keeps for generate(). Owned by the plugin until wp_destroy. */
typedef struct wp_state {
    wp_config cfg;
    wp_leaf_form leaf;      /* the leaf drawn at each frame; empty when the species has no leaves */
    wp_caps caps;
    int32_t bark_material;
    int32_t leaf_material;  /* -1 without leaves */
    plugin_last_stats last; /* the figures of the last model generate() built */
} wp_state;

/* What the card's texture shows: the texture the leaf material gets, drawn here once more. */
static int card_texture_fit(const wp_config *c, wp_leaf_texture_fit *fit, plugin_err *err)
{
    const uint32_t n = WP_LEAF_TEXTURE_SIZE;
    uint8_t *rgba = malloc((size_t)n * n * 4); /* owned here */
    if (!rgba) return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for the leaf texture");
    char why[256];
    int rc = leaf_affine_render(&c->leaf_maps, n, WP_LEAF_TEXTURE_SEED, rgba, why, sizeof why)
                 ? plugin_fail(err, SYLVA_ERR_NOMEM, "the leaf texture: %s", why)
                 : SYLVA_OK;
    if (!rc) wp_leaf_texture_fit_of(rgba, n, fit); /* an empty texture leaves fit empty: the card refuses it */
    free(rgba);
    return rc;
}

/* The leaf form of the species: its own shape or a card over it. */
static int make_leaf(wp_state *st, plugin_err *err)
{
    const wp_config *c = &st->cfg;
    if (!c->species.leaves) return SYLVA_OK;
    wp_leaf_shape shape = {0}; /* owned here */
    plugin_err why = {0};
    int rc = wp_leaf_shape_make(&c->species, &shape, &why);
    if (rc) {
        const sylva_params *where = c->model ? c->model : c->where;
        return plugin_fail_key(err, rc, where, c->model ? "leaf_shape" : "file", "%s", why.msg);
    }
    wp_leaf_texture_fit fit = {0};
    if (c->leaf == WP_LEAF_OWN)
        rc = wp_leaf_form_own(&shape, &st->leaf, &why);
    else if (!(rc = card_texture_fit(c, &fit, &why)))
        rc = wp_leaf_form_card(&shape, &fit, &st->leaf, &why);
    wp_leaf_shape_release(&shape);
    return rc ? plugin_fail_key(err, rc, c->where, rc == SYLVA_ERR_PARAM ? "leaf" : NULL, "%s", why.msg) : SYLVA_OK;
}

/* The host's memory_check as wp_caps_fit's question. */
static int fits_budget(void *ctx, uint64_t bytes)
{
    const plugin_host_ref *h = ctx;
    char what[160];
    snprintf(what, sizeof what, "tree_weber_penn: one model of %llu bytes",
             (unsigned long long)bytes);
    return h->api->memory_check(h->host, bytes, 0, what) == SYLVA_OK;
}

static int make_materials(const sylva_host_api *api, sylva_host *host, wp_state *st)
{
    const wp_config *c = &st->cfg;
    st->bark_material = plugin_bark_material(api, host, "tree_weber_penn.bark", &c->bark, WP_BARK_TEXTURE_SIZE,
                                             c->bark_color);
    if (st->bark_material < 0) return st->bark_material;
    st->leaf_material = -1;
    if (!st->leaf.nt) return SYLVA_OK;
    st->leaf_material = plugin_leaf_material(api, host, "tree_weber_penn.leaf",
                                             c->leaf == WP_LEAF_CARD ? &c->leaf_maps : NULL, WP_LEAF_TEXTURE_SIZE,
                                             WP_LEAF_TEXTURE_SEED, c->leaf_color, c->leaf_transmittance);
    return st->leaf_material < 0 ? st->leaf_material : SYLVA_OK;
}

static void wp_destroy(void *state)
{
    wp_state *st = state;
    if (!st) return;
    wp_leaf_form_release(&st->leaf);
    plugin_last_stats_release(&st->last);
    free(st);
}

static int wp_create(const sylva_host_api *api, sylva_host *host, const sylva_params *params, void **state)
{
    *state = NULL;
    wp_state *st = calloc(1, sizeof *st); /* owned by the plugin until wp_destroy */
    if (!st) {
        api->error(host, "tree_weber_penn: out of memory for its settings");
        return SYLVA_ERR_NOMEM;
    }
    plugin_last_stats_init(&st->last);
    plugin_err err = {0};
    plugin_params r = plugin_params_open(api, host, params);
    int rc = wp_config_read(&r, &st->cfg, &err) ? plugin_params_report(&r, &err) : SYLVA_OK;
    if (!rc && make_leaf(st, &err)) rc = plugin_report(api, host, &err);
    if (!rc) {
        plugin_host_ref h = {api, host};
        int budget = SYLVA_API_HAS(api, memory_check);
        wp_caps_fit(st->leaf.nt, budget ? fits_budget : NULL, &h, &st->caps);
        rc = make_materials(api, host, st);
    }
    if (rc) {
        wp_destroy(st);
        return rc;
    }
    *state = st;
    return SYLVA_OK;
}

/* A tree past the caps: the grower's sentence (or the count), what bounds the model, what to
 * change; at the key the species came from. */
static int refuse_size(const wp_state *st, double age, const char *why, plugin_err *err)
{
    const wp_config *c = &st->cfg;
    return plugin_fail_key(err, SYLVA_ERR_LIMIT, c->where, c->where_key,
                           "the tree at age %g is too large: %s; one model may hold %zu triangles (%zu leaves of "
                           "this leaf), %s; lower model.levels, model.branches or model.leaves, or "
                           "model.leaf_quality below 1%s",
                           age, why, st->caps.triangles, st->caps.leaves,
                           st->caps.by_memory ? "all the memory budget allows" : "the host's limit per model",
                           st->caps.by_memory ? ", or give sylva more memory (SYLVA_MEMORY_LIMIT)" : "");
}

/* Grows the species at `age` with `seed` into *m, held to the caps. */
static int grow(const wp_state *st, const wp_params *p, int64_t seed, double age, wp_model *m, plugin_err *err)
{
    plugin_err why = {0};
    int rc = wp_model_grow(p, seed, st->caps.triangles, st->caps.leaves, m, &why);
    if (rc == SYLVA_ERR_LIMIT) return refuse_size(st, age, why.msg, err);
    if (rc) {
        *err = why;
        return rc;
    }
    uint64_t total = (uint64_t)m->n_triangles + (uint64_t)m->n_leaves * st->leaf.nt;
    if (total > st->caps.triangles) {
        char count[160];
        snprintf(count, sizeof count, "%zu stem triangles and %zu leaves of %u triangles make %llu",
                 m->n_triangles, m->n_leaves, st->leaf.nt, (unsigned long long)total);
        wp_model_release(m);
        return refuse_size(st, age, count, err);
    }
    return SYLVA_OK;
}

static int wp_generate(void *state, const sylva_host_api *api, sylva_host *host, const void *request, void *out)
{
    wp_state *st = state;
    const sylva_tree_request *req = request;
    sylva_tree_out *o = out;
    if (req->size < offsetof(sylva_tree_request, seed) + sizeof req->seed ||
        o->size < offsetof(sylva_tree_out, height) + sizeof o->height) {
        api->error(host, "tree_weber_penn: the host's tree request or output is too small");
        return SYLVA_ERR_INTERNAL;
    }
    if (!(req->age > 0.0 && req->age <= 1.0))
        return api->error(host, "tree_weber_penn: variant age %g is outside (0, 1]", req->age);
    wp_params p;
    wp_params_at_age(&st->cfg.species, req->age, &p);
    int64_t seed = wp_variant_seed(st->cfg.seed, req->variant, req->n_variants);
    plugin_err err = {0};
    wp_model m = {0};
    wp_host_mesh w = {0};
    int rc = grow(st, &p, seed, req->age, &m, &err);
    if (!rc) rc = wp_host_mesh_build(&m, &st->leaf, st->bark_material, st->leaf_material, &w, &err);
    if (rc) rc = plugin_report(api, host, &err);
    sylva_tree_stats last = {.size = sizeof last, .age = req->age};
    if (!rc && wp_stats_measure(&m, p.levels, &w, &last)) {
        api->error(host, "tree_weber_penn: out of memory measuring the tree's silhouette");
        rc = SYLVA_ERR_NOMEM;
    }
    wp_model_release(&m);
    if (!rc) rc = api->mesh_append(host, o->mesh, w.pos, w.nrm, w.uv, w.nv, w.tri, w.mat, w.nt);
    if (!rc) o->height = w.top;
    plugin_last_stats_set(&st->last, rc ? NULL : &last);
    wp_host_mesh_release(&w);
    return rc;
}

static int wp_last_stats(void *state, sylva_tree_stats *out)
{
    wp_state *st = state;
    return st ? plugin_last_stats_get(&st->last, out) : SYLVA_ERR_PARAM;
}

static const sylva_tree_stats_v1 stats_interface = {.size = sizeof stats_interface, .last_stats = wp_last_stats};

static const void *wp_extension(const char *name)
{
    return name && !strcmp(name, SYLVA_TREE_STATS_V1) ? &stats_interface : NULL;
}

static const sylva_plugin wp_descriptor = {
    .size = sizeof(sylva_plugin),
    .abi_major = SYLVA_ABI_MAJOR,
    .abi_minor = SYLVA_ABI_MINOR,
    .param_spec_size = sizeof(sylva_param_spec),
    .kind = SYLVA_KIND_TREE,
    .name = "tree_weber_penn",
    .summary = "Weber-Penn trees grown as Arbaro grows them, from Arbaro or Helios species files or inline "
               "parameters.",
    .version = "1.0",
    .params = wp_schema,
    .n_params = WP_SCHEMA_COUNT,
    .create = wp_create,
    .generate = wp_generate,
    .destroy = wp_destroy,
    .extension = wp_extension,
    .flags = SYLVA_PLUGIN_CONCURRENT_GENERATE, /* generate() writes only st->last, under its lock */
};

const sylva_plugin *wp_plugin(void) { return &wp_descriptor; }
