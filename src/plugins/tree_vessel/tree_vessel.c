/* tree_vessel.c — the tree_vessel plugin: Holton's vessel model as modified in 004 ch. 3.
 *
 * create() reads the species' block (a preset, then the keys the scene gives), and makes the
 * bark and leaf textures and materials once for the species. generate() builds one variant:
 * the branch structure for the request's age and level of detail (vessel_structure.h), then
 * its mesh (vessel_mesh.h), which it hands to the host in one mesh_append. The plugin keeps no
 * global state; the wind phases come from the host's stream "tree_vessel.wind" for the
 * variant. What this file allocates goes through the host's allocator (ABI 1.1), so the host's
 * limits and fault tests reach it; the model's own buffers use the C library's. */
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "plugin_host.h"
#include "sylva/plugin.h"
#include "sylva/tree_stats.h"
#include "tree_look.h"
#include "vessel_config.h"
#include "vessel_mesh.h"
#include "vessel_presets.h"
#include "vessel_stats.h"
#include "vessel_structure.h"
#include "vessel_texture.h"

/* The plugin's state for one species: owned by the plugin, freed by tree_vessel_destroy with the
 * host's mem_free it keeps (destroy receives no table). */
typedef struct tree_vessel_state {
    vessel_params params;
    int32_t bark_material, leaf_material;
    void (*mem_free)(void *);
    plugin_last_stats last; /* the figures of the last model generate() built */
} tree_vessel_state;

/* Textures and materials for the species; returns 0 or a negative status (message set). */
static int make_materials(const sylva_host_api *api, sylva_host *host, tree_vessel_state *s)
{
    const vessel_params *p = &s->params;
    uint8_t *bark = api->mem_alloc(VESSEL_BARK_TEXTURE_SIZE * VESSEL_BARK_TEXTURE_SIZE * 4); /* owned here */
    uint8_t *leaf = api->mem_alloc(VESSEL_LEAF_TEXTURE_SIZE * VESSEL_LEAF_TEXTURE_SIZE * 4); /* owned here */
    int rc = SYLVA_OK;
    if (!bark || !leaf) {
        api->error(host, "tree_vessel: out of memory for the bark and leaf textures");
        rc = SYLVA_ERR_NOMEM;
        goto done;
    }
    char name[64];
    vessel_texture_bark(p, bark);
    snprintf(name, sizeof name, "tree_vessel bark %s", tree_look_bark_names[p->bark_preset]);
    int32_t bark_tex = api->texture_new(host, name, VESSEL_BARK_TEXTURE_SIZE,
                                        VESSEL_BARK_TEXTURE_SIZE, bark);
    if (vessel_texture_leaf(p, leaf)) {
        api->error(host, "tree_vessel: out of memory for the leaf texture");
        rc = SYLVA_ERR_NOMEM;
        goto done;
    }
    snprintf(name, sizeof name, "tree_vessel leaf %s",
             p->leaf_preset >= 0 ? leaf_affine_preset_name((leaf_affine_preset)p->leaf_preset) : "maps");
    int32_t leaf_tex = api->texture_new(host, name, VESSEL_LEAF_TEXTURE_SIZE,
                                        VESSEL_LEAF_TEXTURE_SIZE, leaf);
    if (bark_tex < 0 || leaf_tex < 0) {
        rc = bark_tex < 0 ? bark_tex : leaf_tex;
        goto done;
    }
    sylva_material_desc d = {.size = sizeof d, .name = "tree_vessel bark", .bsdf = SYLVA_BSDF_LAMBERT,
                             .texture = bark_tex};
    for (int k = 0; k < 3; k++) d.albedo[k] = p->bark_albedo[k];
    s->bark_material = api->material_new(host, &d);
    d = (sylva_material_desc){.size = sizeof d, .name = "tree_vessel leaf", .bsdf = SYLVA_BSDF_LEAF,
                              .texture = leaf_tex, .alpha_mask = 1};
    for (int k = 0; k < 3; k++) d.albedo[k] = p->leaf_albedo[k], d.transmittance[k] = p->leaf_transmittance[k];
    s->leaf_material = api->material_new(host, &d);
    if (s->bark_material < 0 || s->leaf_material < 0)
        rc = s->bark_material < 0 ? s->bark_material : s->leaf_material;
done:
    api->mem_free(bark);
    api->mem_free(leaf);
    return rc;
}

static int tree_vessel_create(const sylva_host_api *api, sylva_host *host,
                              const sylva_params *params, void **state)
{
    *state = NULL;
    if (!SYLVA_API_HAS(api, mem_alloc))
        return api->error(host, "tree_vessel needs a host with sylva plugin ABI 1.1 or newer (for "
                          "its allocator); this host speaks %u.%u", api->abi_major, api->abi_minor);
    tree_vessel_state *s = api->mem_calloc(1, sizeof *s); /* owned by the plugin until destroy */
    if (!s) {
        api->error(host, "tree_vessel: out of memory for the species' parameters");
        return SYLVA_ERR_NOMEM;
    }
    s->mem_free = api->mem_free;
    plugin_err err = {0};
    plugin_params r = plugin_params_open(api, host, params);
    if (vessel_config_read(&r, &s->params, &err)) {
        api->mem_free(s);
        if (r.status) return r.status; /* the host has the sentence */
        if (err.param[0]) api->param_error(host, params, err.param, "%s", err.msg);
        else api->error(host, "tree_vessel: %s", err.msg);
        return (int)err.status;
    }
    int rc = make_materials(api, host, s);
    if (rc) {
        api->mem_free(s);
        return rc;
    }
    plugin_last_stats_init(&s->last);
    *state = s;
    return SYLVA_OK;
}

/* Adapts the host's stream to the model's number source. */
typedef struct wind_stream {
    const sylva_host_api *api;
    sylva_rng rng;
} wind_stream;

static double wind_uniform(void *ctx)
{
    wind_stream *w = ctx;
    return w->api->rng_uniform(&w->rng);
}

static int tree_vessel_generate(void *state, const sylva_host_api *api, sylva_host *host,
                                const void *request, void *out)
{
    tree_vessel_state *s = state;
    const sylva_tree_request *req = request;
    sylva_tree_out *o = out;
    if (req->size < offsetof(sylva_tree_request, seed) + sizeof req->seed ||
        o->size < offsetof(sylva_tree_out, height) + sizeof o->height) {
        api->error(host, "tree_vessel: the host's tree request (%u bytes) or output (%u bytes) is "
                   "smaller than this plugin reads", req->size, o->size);
        return SYLVA_ERR_INTERNAL;
    }
    wind_stream wind = {.api = api};
    api->rng_init(host, &wind.rng, "tree_vessel.wind", req->variant);
    vessel_growth growth = {.age = req->age, .lod = req->lod, .uniform = wind_uniform, .ctx = &wind};

    plugin_err err = {0};
    vessel_tree tree = {0};  /* owned here */
    vessel_mesh mesh = {0};  /* owned here */
    int rc = SYLVA_OK;
    if (vessel_tree_grow(&s->params, &growth, &tree, &err) ||
        vessel_mesh_build(&tree, &s->params, s->bark_material, s->leaf_material, &mesh, &err)) {
        api->error(host, "tree_vessel: %s", err.msg);
        rc = (int)err.status;
        goto done;
    }
    api->log(host, SYLVA_LOG_DEBUG,
             "tree_vessel: age %.3g, lod %u: S' = %u, %u segments, %u leaf-bearing, %u bark and %u "
             "leaf triangles, %.2f m high", req->age, req->lod, tree.vessels, tree.n, tree.n_terminal,
             mesh.bark_triangles, mesh.leaf_triangles, mesh.top);
    rc = api->mesh_append(host, o->mesh, mesh.pos, mesh.nrm, mesh.uv, mesh.nv, mesh.tri, mesh.mat,
                          mesh.nt);
    if (rc == SYLVA_OK) {
        o->height = mesh.top;
        sylva_tree_stats last = {.size = sizeof last, .age = req->age};
        if (vessel_stats_measure(&tree, &mesh, &last)) {
            api->error(host, "tree_vessel: out of memory measuring the tree's silhouette");
            rc = SYLVA_ERR_NOMEM;
        }
        plugin_last_stats_set(&s->last, rc == SYLVA_OK ? &last : NULL);
    }
done:
    vessel_mesh_release(&mesh);
    vessel_tree_release(&tree);
    return rc;
}

static int tree_vessel_last_stats(void *state, sylva_tree_stats *out)
{
    tree_vessel_state *s = state;
    return s ? plugin_last_stats_get(&s->last, out) : SYLVA_ERR_PARAM;
}

static const sylva_tree_stats_v1 stats_interface = {.size = sizeof stats_interface,
                                                    .last_stats = tree_vessel_last_stats};

static const void *tree_vessel_extension(const char *name)
{
    return name && !strcmp(name, SYLVA_TREE_STATS_V1) ? &stats_interface : NULL;
}

static void tree_vessel_destroy(void *state)
{
    tree_vessel_state *s = state;
    if (!s) return;
    plugin_last_stats_release(&s->last);
    s->mem_free(s);
}

static const sylva_plugin tree_vessel = {
    .size = sizeof(sylva_plugin),
    .abi_major = SYLVA_ABI_MAJOR,
    .abi_minor = SYLVA_ABI_MINOR,
    .param_spec_size = sizeof(sylva_param_spec),
    .kind = SYLVA_KIND_TREE,
    .name = "tree_vessel",
    .summary = "Holton's vessel tree model as modified in EcoMod (beech, spruce, weeping willow, maple).",
    .version = "1.0",
    .params = vessel_schema,
    .n_params = VESSEL_SCHEMA_COUNT,
    .create = tree_vessel_create,
    .generate = tree_vessel_generate,
    .destroy = tree_vessel_destroy,
    .extension = tree_vessel_extension,
    .preset_param = "preset",
    .presets = vessel_presets,
    .n_presets = VESSEL_PRESETS,
    .flags = SYLVA_PLUGIN_CONCURRENT_GENERATE, /* generate() writes only s->last, under its lock */
};

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    return index == 0 ? &tree_vessel : NULL;
}
