/* tree_aono_kunii.c — the plugin file: the descriptor and its operations — parameters and
 * materials in create(), one age variant per generate() (skeleton, bark, leaves, one
 * mesh_append), and destroy(). The only file of the plugin that calls the host: the model
 * (aono_config, aono_grow, aono_mesh) reports failures in a plugin_err, which plugin_report()
 * hands to api->error or api->param_error, and takes its random streams and progress from an aono_env
 * made of the host's. aono_entry.c exports the descriptor. */
#include "tree_aono_kunii.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "aono_config.h"
#include "aono_grow.h"
#include "aono_mesh.h"
#include "aono_stats.h"
#include "plugin_host.h"
#include "sylva/tree_stats.h"

/* What create() keeps for generate(). Owned by the plugin until aono_destroy. */
typedef struct aono_state {
    aono_config cfg;
    int32_t bark_material;
    int32_t leaf_material; /* -1 without leaves */
    plugin_last_stats last; /* the figures of the last model generate() built */
} aono_state;

static void host_progress(void *ctx, uint32_t levels_done, uint32_t levels)
{
    const plugin_host_ref *h = ctx;
    h->api->progress(h->host, "tree_aono_kunii levels", levels_done, levels);
}

uint32_t aono_variant_levels(uint32_t levels, double age)
{
    double n = ceil(age * levels - 1e-9);
    if (!(n >= 1.0)) return 1;
    return n > levels ? levels : (uint32_t)n;
}

/* A texture of size x size texels drawn by fill; returns its id or a negative status. */
static int32_t make_texture(const sylva_host_api *api, sylva_host *host, const aono_config *c, const char *name,
                            uint32_t size, int (*fill)(const aono_config *, uint8_t *))
{
    uint8_t *texels = malloc(4u * size * size); /* owned here; the host copies */
    if (!texels || fill(c, texels)) {
        free(texels);
        api->error(host, "tree_aono_kunii: out of memory for the %s texture", name);
        return SYLVA_ERR_NOMEM;
    }
    int32_t tex = api->texture_new(host, name, size, size, texels);
    free(texels);
    return tex;
}

static int make_materials(const sylva_host_api *api, sylva_host *host, aono_state *st)
{
    const aono_config *c = &st->cfg;
    int32_t tex = make_texture(api, host, c, "tree_aono_kunii.bark", AONO_BARK_TEXTURE_SIZE, aono_bark_texture);
    if (tex < 0) return tex;
    sylva_material_desc bark = {.size = sizeof bark, .name = "tree_aono_kunii.bark", .bsdf = SYLVA_BSDF_LAMBERT,
                                .texture = tex};
    for (int k = 0; k < 3; k++) bark.albedo[k] = (float)c->bark_color[k];
    st->bark_material = api->material_new(host, &bark);
    if (st->bark_material < 0) return st->bark_material;
    st->leaf_material = -1;
    if (!c->leaf_count) return SYLVA_OK;
    tex = make_texture(api, host, c, "tree_aono_kunii.leaf", AONO_LEAF_TEXTURE_SIZE, aono_leaf_texture);
    if (tex < 0) return tex;
    sylva_material_desc leaf = {.size = sizeof leaf, .name = "tree_aono_kunii.leaf", .bsdf = SYLVA_BSDF_LEAF,
                                .texture = tex, .alpha_mask = 1};
    for (int k = 0; k < 3; k++)
        leaf.albedo[k] = (float)c->leaf_color[k], leaf.transmittance[k] = (float)c->leaf_transmittance[k];
    st->leaf_material = api->material_new(host, &leaf);
    return st->leaf_material < 0 ? st->leaf_material : SYLVA_OK;
}

static void aono_destroy(void *state)
{
    aono_state *st = state;
    if (!st) return;
    aono_config_release(&st->cfg);
    plugin_last_stats_release(&st->last);
    free(st);
}

static int aono_create(const sylva_host_api *api, sylva_host *host, const sylva_params *params, void **state)
{
    *state = NULL;
    aono_state *st = calloc(1, sizeof *st); /* owned by the plugin until aono_destroy */
    if (!st) {
        api->error(host, "tree_aono_kunii: out of memory for its settings");
        return SYLVA_ERR_NOMEM;
    }
    plugin_last_stats_init(&st->last);
    plugin_err err = {0};
    plugin_params r = plugin_params_open(api, host, params);
    int rc = aono_config_read(&r, &st->cfg, &err) ? plugin_params_report(&r, &err) : SYLVA_OK;
    if (!rc) rc = make_materials(api, host, st);
    if (rc) {
        aono_destroy(st);
        return rc;
    }
    *state = st;
    return SYLVA_OK;
}

static int aono_generate(void *state, const sylva_host_api *api, sylva_host *host, const void *request, void *out)
{
    aono_state *st = state;
    const sylva_tree_request *req = request;
    sylva_tree_out *o = out;
    if (req->size < offsetof(sylva_tree_request, age) + sizeof req->age ||
        o->size < offsetof(sylva_tree_out, height) + sizeof o->height) {
        api->error(host, "tree_aono_kunii: the host's tree request or output is too small");
        return SYLVA_ERR_INTERNAL;
    }
    if (!(req->age > 0.0 && req->age <= 1.0))
        return api->error(host, "tree_aono_kunii: variant age %g is outside (0, 1]", req->age);
    plugin_host_ref h = {api, host};
    aono_env env = {.stream = plugin_host_stream, .uniform = api->rng_uniform, .progress = host_progress,
                    .ctx = &h};
    plugin_err err = {0};
    aono_skeleton skel;
    aono_mesh_buffer buf = {0};
    if (aono_grow(&st->cfg, aono_variant_levels(st->cfg.levels, req->age), &env, &skel, &err))
        return plugin_report(api, host, &err);
    int rc = aono_mesh_branches(&st->cfg, &skel, st->bark_material, &buf, &err);
    if (!rc) rc = aono_mesh_leaves(&st->cfg, &skel, st->leaf_material, &env, &buf, &err);
    if (rc) rc = plugin_report(api, host, &err);
    sylva_tree_stats last = {.size = sizeof last, .age = req->age};
    if (!rc && aono_stats_measure(&skel, &buf, st->leaf_material, &last)) {
        api->error(host, "tree_aono_kunii: out of memory measuring the tree's silhouette");
        rc = SYLVA_ERR_NOMEM;
    }
    aono_skeleton_release(&skel);
    if (!rc) rc = api->mesh_append(host, o->mesh, buf.pos, buf.nrm, buf.uv, buf.nv, buf.tri, buf.mat, buf.nt);
    if (!rc) o->height = last.height;
    plugin_last_stats_set(&st->last, rc ? NULL : &last);
    aono_mesh_buffer_release(&buf);
    return rc;
}

static int aono_last_stats(void *state, sylva_tree_stats *out)
{
    aono_state *st = state;
    return st ? plugin_last_stats_get(&st->last, out) : SYLVA_ERR_PARAM;
}

static const sylva_tree_stats_v1 stats_interface = {.size = sizeof stats_interface, .last_stats = aono_last_stats};

static const void *aono_extension(const char *name)
{
    return name && !strcmp(name, SYLVA_TREE_STATS_V1) ? &stats_interface : NULL;
}

static const sylva_plugin aono_descriptor = {
    .size = sizeof(sylva_plugin),
    .abi_major = SYLVA_ABI_MAJOR,
    .abi_minor = SYLVA_ABI_MINOR,
    .param_spec_size = sizeof(sylva_param_spec),
    .kind = SYLVA_KIND_TREE,
    .name = "tree_aono_kunii",
    .summary = "Aono-Kunii branching trees with attractors and inhibitors (Petric's CAVIA model).",
    .version = "1.0",
    .params = aono_params,
    .n_params = AONO_N_PARAMS,
    .create = aono_create,
    .generate = aono_generate,
    .destroy = aono_destroy,
    .extension = aono_extension,
    .flags = SYLVA_PLUGIN_CONCURRENT_GENERATE, /* generate() writes only st->last, under its lock */
};

const sylva_plugin *aono_plugin(void) { return &aono_descriptor; }
