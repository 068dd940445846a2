/* broken_abi.c — a test module built "against" a future major ABI (99): the host must refuse it
 * with "built against sylva plugin ABI 99.0, this host speaks 1.0; rebuild the plugin" and must
 * not read any field past the version. Otherwise a valid flat terrain plugin. */
#include "sylva/plugin.h"

#include "flat_terrain_ops.h"

static const sylva_plugin broken_abi = {
    .size = sizeof(sylva_plugin),
    .abi_major = 99,
    .abi_minor = 0,
    .param_spec_size = sizeof(sylva_param_spec),
    .kind = SYLVA_KIND_TERRAIN,
    .name = "broken_abi",
    .summary = "A flat terrain declaring ABI 99.0.",
    .version = "1.0",
    .create = flat_create,
    .generate = flat_generate,
    .destroy = flat_destroy,
};

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    return index == 0 ? &broken_abi : NULL;
}
