/* plugin_host.h — the adapters a plugin file uses to hand its model what the model takes as
 * plain data and callbacks: the model's failure to the host, and the host's keyed random
 * streams as a `stream` callback. Only plugin files call these (they call the host). */
#ifndef PLUGIN_HOST_H
#define PLUGIN_HOST_H

#include <pthread.h>

#include "bark_fractal.h"
#include "leaf_affine.h"
#include "plugin_err.h"
#include "sylva/plugin.h"
#include "sylva/tree_stats.h"

/* The host of one call, as the ctx of a model's callbacks. Lives on the caller's stack. */
typedef struct plugin_host_ref {
    const sylva_host_api *api;
    sylva_host *host;
} plugin_host_ref;

/* Hands err to the host (api->param_error at its key when it names one, else api->error) and
 * returns its status (SYLVA_ERR_INTERNAL when none was set). */
int plugin_report(const sylva_host_api *api, sylva_host *host, const plugin_err *err);

/* A model's `stream` callback: api->rng_init on the host of ctx (a plugin_host_ref). */
void plugin_host_stream(void *ctx, sylva_rng *rng, const char *purpose, uint64_t index);

/* The "sylva.tree_stats.v1" interface's last_stats for a plugin that keeps its last model's
 * figures: copies *last into *out up to out->size (the caller's struct may be older and
 * smaller). Returns SYLVA_OK, or SYLVA_ERR_PARAM when has_last is 0 or out is unusable. */
int plugin_tree_stats_copy(const sylva_tree_stats *last, int has_last, sylva_tree_stats *out);

/* Sets st's bbox_min and bbox_max from a model's nv vertices (pos: 3 * nv, metres); both 0 for
 * an empty model. */
void plugin_tree_stats_bounds(sylva_tree_stats *st, const float *pos, uint32_t nv);

/* A tree plugin's bark material `name`: Lambert, albedo `color` (linear RGB) times the fractal
 * bark texture of `bark` (size x size texels, tree_look_bark_texture). Returns its id, or a
 * negative status with the host's sentence set. */
int32_t plugin_bark_material(const sylva_host_api *api, sylva_host *host, const char *name,
                             const bark_fractal_params *bark, uint32_t size, const double color[3]);

/* A tree plugin's leaf material `name`: SYLVA_BSDF_LEAF of albedo `color` and `transmittance`
 * (linear RGB) times the affine-map leaf texture of `maps` (size x size texels, chaos-game seed
 * `seed`, alpha-masked to its outline), or plain when maps is NULL. Returns its id, or a negative
 * status with the host's sentence set. */
int32_t plugin_leaf_material(const sylva_host_api *api, sylva_host *host, const char *name,
                             const leaf_affine_maps *maps, uint32_t size, uint64_t seed, const double color[3],
                             const double transmittance[3]);

/* A tree plugin's last model's figures, kept under a lock so that generate() calls running at
 * once (SYLVA_PLUGIN_CONCURRENT_GENERATE) may each set them: last_stats then gives the figures
 * of whichever finished last (`sylva tree-stats` asks after each call, one at a time). */
typedef struct plugin_last_stats {
    pthread_mutex_t lock;
    sylva_tree_stats stats;
    int has;
} plugin_last_stats;

void plugin_last_stats_init(plugin_last_stats *l);
void plugin_last_stats_release(plugin_last_stats *l); /* accepts NULL */
/* Keeps *st as the last figures; st NULL: there are none (the last call failed). */
void plugin_last_stats_set(plugin_last_stats *l, const sylva_tree_stats *st);
/* plugin_tree_stats_copy of the kept figures. */
int plugin_last_stats_get(plugin_last_stats *l, sylva_tree_stats *out);

#endif
