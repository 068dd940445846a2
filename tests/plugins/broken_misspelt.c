/* broken_misspelt.c — a test terrain plugin whose create() reads its one parameter under a
 * misspelt name ('amplitdue' for 'amplitude') through the checked reader of sylva/plugin.h. The
 * scene is valid (its key is the schema's); the host must stop it with a sentence naming the
 * misspelt name and the parameters the schema has, at the plugin's block, instead of the plugin
 * building its terrain from a silent 0. */
#include <stddef.h>

#include "flat_terrain_ops.h"

static const sylva_param_spec broken_misspelt_params[] = {
    {.name = "amplitude", .type = SYLVA_P_REAL, .def = 1.0, .help = "Height of the flat terrain, metres."},
};

static int broken_misspelt_create(const sylva_host_api *api, sylva_host *host, const sylva_params *params,
                                  void **state)
{
    double amplitude = 0.0;
    int rc = sylva_param_real_checked(api, host, params, "amplitdue", &amplitude);
    if (rc) return rc;
    return flat_create(api, host, params, state);
}

static const sylva_plugin broken_misspelt = {
    .size = sizeof(sylva_plugin),
    .abi_major = SYLVA_ABI_MAJOR,
    .abi_minor = SYLVA_ABI_MINOR,
    .param_spec_size = sizeof(sylva_param_spec),
    .kind = SYLVA_KIND_TERRAIN,
    .name = "broken_misspelt",
    .summary = "A flat terrain whose create() reads a misspelt parameter name (for tests).",
    .version = "1.0",
    .params = broken_misspelt_params,
    .n_params = 1,
    .create = broken_misspelt_create,
    .generate = flat_generate,
    .destroy = flat_destroy,
};

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    return index == 0 ? &broken_misspelt : NULL;
}
