/* broken_create.c — a test terrain plugin whose descriptor is valid but whose create() always
 * refuses its 'roughness' parameter through api->param_error. The host must load it, then stop
 * the scene with the plugin's sentence prefixed by the parameter's file:line:column, never
 * calling generate() and calling destroy() at most with NULL. */
#include <stddef.h>

#include "sylva/plugin.h"

static const sylva_param_spec broken_create_params[] = {
    {.name = "roughness", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX,
     .def = 0.5, .min = 0.0, .max = 1.0,
     .help = "Any value in the schema's range; create() refuses every one of them."},
};

static int broken_create_create(const sylva_host_api *api, sylva_host *host,
                                const sylva_params *params, void **state)
{
    *state = NULL;
    return api->param_error(host, params, "roughness", "roughness %g is refused: broken_create "
                            "refuses every value, to test how the host reports create() errors",
                            sylva_param_real(params, "roughness"));
}

static int broken_create_generate(void *state, const sylva_host_api *api, sylva_host *host,
                                  const void *request, void *out)
{
    return api->error(host, "broken_create: generate() ran although create() failed");
}

static void broken_create_destroy(void *state) { (void)state; }

static const sylva_plugin broken_create = {
    .size = sizeof(sylva_plugin),
    .abi_major = SYLVA_ABI_MAJOR,
    .abi_minor = SYLVA_ABI_MINOR,
    .param_spec_size = sizeof(sylva_param_spec),
    .kind = SYLVA_KIND_TERRAIN,
    .name = "broken_create",
    .summary = "A terrain whose create() always fails (for tests).",
    .version = "1.0",
    .params = broken_create_params,
    .n_params = 1,
    .create = broken_create_create,
    .generate = broken_create_generate,
    .destroy = broken_create_destroy,
};

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    return index == 0 ? &broken_create : NULL;
}
