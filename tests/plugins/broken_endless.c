/* broken_endless.c — a test module whose entry point never returns NULL (it ignores the index):
 * the host must stop at its descriptor limit and refuse the module with one problem, instead of
 * asking forever or listing the same plugin many times. */
#include "sylva/plugin.h"

#include "flat_terrain_ops.h"

static const sylva_plugin broken_endless = {
    .size = sizeof(sylva_plugin),
    .abi_major = SYLVA_ABI_MAJOR,
    .abi_minor = SYLVA_ABI_MINOR,
    .param_spec_size = sizeof(sylva_param_spec),
    .kind = SYLVA_KIND_TERRAIN,
    .name = "broken_endless",
    .summary = "A flat terrain listed at every index.",
    .version = "1.0",
    .create = flat_create,
    .generate = flat_generate,
    .destroy = flat_destroy,
};

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    (void)index;
    return &broken_endless;
}
