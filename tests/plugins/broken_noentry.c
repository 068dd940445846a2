/* broken_noentry.c — a test module whose entry point is not exported (it lacks SYLVA_EXPORT and
 * is hidden): the host must report "no entry point [sylva_plugin_get] in shared library [...]".
 */
#include "sylva/plugin.h"

#include "flat_terrain_ops.h"

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
