/* plugin_host.c — a plugin model's failure and random streams through the host's API table, and
 * its last model's figures to the host. */
#include "plugin_host.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "tree_look.h"

int plugin_report(const sylva_host_api *api, sylva_host *host, const plugin_err *err)
{
    if (err->param[0]) api->param_error(host, err->where, err->param, "%s", err->msg);
    else api->error(host, "%s", err->msg);
    return err->status ? err->status : SYLVA_ERR_INTERNAL;
}

void plugin_host_stream(void *ctx, sylva_rng *rng, const char *purpose, uint64_t index)
{
    const plugin_host_ref *h = ctx;
    h->api->rng_init(h->host, rng, purpose, index);
}

int plugin_tree_stats_copy(const sylva_tree_stats *last, int has_last, sylva_tree_stats *out)
{
    if (!has_last || !out || out->size < sizeof out->size) return SYLVA_ERR_PARAM;
    uint32_t size = out->size < sizeof *out ? out->size : (uint32_t)sizeof *out;
    memcpy((char *)out + sizeof out->size, (const char *)last + sizeof out->size, size - sizeof out->size);
    return SYLVA_OK;
}

void plugin_tree_stats_bounds(sylva_tree_stats *st, const float *pos, uint32_t nv)
{
    for (int k = 0; k < 3; k++) st->bbox_min[k] = nv ? DBL_MAX : 0, st->bbox_max[k] = nv ? -DBL_MAX : 0;
    for (uint32_t v = 0; v < nv; v++)
        for (int k = 0; k < 3; k++) {
            double x = pos[3 * v + k];
            if (x < st->bbox_min[k]) st->bbox_min[k] = x;
            if (x > st->bbox_max[k]) st->bbox_max[k] = x;
        }
}

/* Texels for a size x size texture (owned by the caller), or NULL with the host's sentence set. */
static uint8_t *texels_new(const sylva_host_api *api, sylva_host *host, const char *name, uint32_t size)
{
    uint8_t *texels = malloc(4u * (size_t)size * size);
    if (!texels) api->error(host, "out of memory for the texture %s", name);
    return texels;
}

/* The material of desc over the texture of `texels` (freed here; NULL: no texture). */
static int32_t material_with(const sylva_host_api *api, sylva_host *host, sylva_material_desc *desc, uint8_t *texels,
                             uint32_t size)
{
    desc->texture = -1;
    if (texels) {
        desc->texture = api->texture_new(host, desc->name, size, size, texels);
        free(texels);
        if (desc->texture < 0) return desc->texture;
    }
    return api->material_new(host, desc);
}

int32_t plugin_bark_material(const sylva_host_api *api, sylva_host *host, const char *name,
                             const bark_fractal_params *bark, uint32_t size, const double color[3])
{
    uint8_t *texels = texels_new(api, host, name, size); /* owned here until material_with */
    if (!texels) return SYLVA_ERR_NOMEM;
    tree_look_bark_texture(bark, size, texels);
    sylva_material_desc d = {.size = sizeof d, .name = name, .bsdf = SYLVA_BSDF_LAMBERT};
    for (int k = 0; k < 3; k++) d.albedo[k] = (float)color[k];
    return material_with(api, host, &d, texels, size);
}

int32_t plugin_leaf_material(const sylva_host_api *api, sylva_host *host, const char *name,
                             const leaf_affine_maps *maps, uint32_t size, uint64_t seed, const double color[3],
                             const double transmittance[3])
{
    uint8_t *texels = NULL; /* owned here until material_with */
    if (maps) {
        if (!(texels = texels_new(api, host, name, size))) return SYLVA_ERR_NOMEM;
        char why[256];
        if (leaf_affine_render(maps, size, seed, texels, why, sizeof why)) {
            free(texels);
            api->error(host, "the texture %s: %s", name, why);
            return SYLVA_ERR_NOMEM;
        }
    }
    sylva_material_desc d = {.size = sizeof d, .name = name, .bsdf = SYLVA_BSDF_LEAF, .alpha_mask = maps != NULL};
    for (int k = 0; k < 3; k++) d.albedo[k] = (float)color[k], d.transmittance[k] = (float)transmittance[k];
    return material_with(api, host, &d, texels, size);
}

void plugin_last_stats_init(plugin_last_stats *l)
{
    memset(l, 0, sizeof *l);
    pthread_mutex_init(&l->lock, NULL);
}

void plugin_last_stats_release(plugin_last_stats *l)
{
    if (l) pthread_mutex_destroy(&l->lock);
}

void plugin_last_stats_set(plugin_last_stats *l, const sylva_tree_stats *st)
{
    pthread_mutex_lock(&l->lock);
    if (st) l->stats = *st;
    l->has = st != NULL;
    pthread_mutex_unlock(&l->lock);
}

int plugin_last_stats_get(plugin_last_stats *l, sylva_tree_stats *out)
{
    pthread_mutex_lock(&l->lock);
    int rc = plugin_tree_stats_copy(&l->stats, l->has, out);
    pthread_mutex_unlock(&l->lock);
    return rc;
}
