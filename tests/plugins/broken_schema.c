/* broken_schema.c — a test module whose schema gives 'amplitude' a default (5 m) above its own
 * maximum (1 m): the host must refuse the plugin, naming the parameter and both numbers. */
#include "sylva/plugin.h"

#include "flat_terrain_ops.h"

static const sylva_param_spec broken_schema_params[] = {
    {.name = "amplitude", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX,
     .def = 5.0, .min = 0.0, .max = 1.0, .unit = "m", .help = "Height of the bumps."},
};

static const sylva_plugin broken_schema = {
    .size = sizeof(sylva_plugin),
    .abi_major = SYLVA_ABI_MAJOR,
    .abi_minor = SYLVA_ABI_MINOR,
    .param_spec_size = sizeof(sylva_param_spec),
    .kind = SYLVA_KIND_TERRAIN,
    .name = "broken_schema",
    .summary = "A flat terrain whose default contradicts its range.",
    .version = "1.0",
    .params = broken_schema_params,
    .n_params = 1,
    .create = flat_create,
    .generate = flat_generate,
    .destroy = flat_destroy,
};

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    return index == 0 ? &broken_schema : NULL;
}
