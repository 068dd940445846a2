/* broken_size.c — a test module whose descriptor records a param_spec_size one double short of
 * the host's sylva_param_spec, as if built against a header with another parameter layout: the
 * host must refuse it before indexing its parameter table. */
#include "sylva/plugin.h"

#include "flat_terrain_ops.h"

static const sylva_param_spec broken_size_params[] = {
    {.name = "height", .type = SYLVA_P_REAL, .def = 0.0, .unit = "m",
     .help = "Height of the flat ground."},
};

static const sylva_plugin broken_size = {
    .size = sizeof(sylva_plugin),
    .abi_major = SYLVA_ABI_MAJOR,
    .abi_minor = SYLVA_ABI_MINOR,
    .param_spec_size = sizeof(sylva_param_spec) - sizeof(double),
    .kind = SYLVA_KIND_TERRAIN,
    .name = "broken_size",
    .summary = "A flat terrain with a mismatched parameter layout.",
    .version = "1.0",
    .params = broken_size_params,
    .n_params = 1,
    .create = flat_create,
    .generate = flat_generate,
    .destroy = flat_destroy,
};

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    return index == 0 ? &broken_size : NULL;
}
