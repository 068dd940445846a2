/* broken_noentry.c — a test module whose entry point is not exported (it lacks SYLVA_EXPORT and
 * is hidden): the host must report "no entry point [sylva_plugin_get] in shared library [...]".
 */
#include "sylva/plugin.h"

static int flat_create(const sylva_host_api *api, sylva_host *host, const sylva_params *params,
                       void **state)
{
    *state = NULL;
    return SYLVA_OK;
}

static int flat_generate(void *state, const sylva_host_api *api, sylva_host *host,
                         const void *request, void *out)
{
    sylva_heightfield *hf = api->heightfield_new(host, 2, 2, 0); /* owned by the host */
    if (!hf) return api->error(host, "cannot allocate a 2 x 2 heightfield");
    hf->dx = hf->dy = 1.0;
    ((sylva_terrain_out *)out)->terrain = hf;
    return SYLVA_OK;
}

static void flat_destroy(void *state) { (void)state; }

static const sylva_plugin broken_noentry = {
    .size = sizeof(sylva_plugin),
    .abi_major = SYLVA_ABI_MAJOR,
    .abi_minor = SYLVA_ABI_MINOR,
    .param_spec_size = sizeof(sylva_param_spec),
    .kind = SYLVA_KIND_TERRAIN,
    .name = "broken_noentry",
    .summary = "A flat terrain nobody can find.",
    .version = "1.0",
    .create = flat_create,
    .generate = flat_generate,
    .destroy = flat_destroy,
};

__attribute__((visibility("hidden"))) const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    return index == 0 ? &broken_noentry : NULL;
}
