/* broken_null.c — a test module whose descriptor has NULL name, summary and version: the host
 * must refuse it with a sentence, without dereferencing any of them. */
#include "sylva/plugin.h"

#include "flat_terrain_ops.h"

static const sylva_plugin broken_null = {
    .size = sizeof(sylva_plugin),
    .abi_major = SYLVA_ABI_MAJOR,
    .abi_minor = SYLVA_ABI_MINOR,
    .param_spec_size = sizeof(sylva_param_spec),
    .kind = SYLVA_KIND_TERRAIN,
    .name = NULL,
    .summary = NULL,
    .version = NULL,
    .create = flat_create,
    .generate = flat_generate,
    .destroy = flat_destroy,
};

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    return index == 0 ? &broken_null : NULL;
}
