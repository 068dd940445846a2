/* probe_constructor.c — a valid flat terrain plugin whose module constructor leaves a mark: it
 * creates $SYLVA_TEST_PROBE_DIR/PROBE_NAME.opened when the module is loaded. Built twice:
 * `probe_open` (with the manifest the build writes) shows which commands open plugin modules;
 * `broken_manifest` (beside a manifest declaring ABI 2.0) must be refused without ever being
 * opened, so its mark must never appear. */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "flat_terrain_ops.h"
#include "sylva/plugin.h"

__attribute__((constructor)) static void probe_mark_opened(void)
{
    const char *dir = getenv("SYLVA_TEST_PROBE_DIR");
    if (!dir) return;
    char path[4096];
    snprintf(path, sizeof path, "%s/%s.opened", dir, PROBE_NAME);
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) close(fd);
}

static const sylva_plugin probe = {
    .size = sizeof(sylva_plugin),
    .abi_major = SYLVA_ABI_MAJOR,
    .abi_minor = SYLVA_ABI_MINOR,
    .param_spec_size = sizeof(sylva_param_spec),
    .kind = SYLVA_KIND_TERRAIN,
    .name = PROBE_NAME,
    .summary = "A flat terrain whose module marks that it was opened.",
    .version = "1.0",
    .create = flat_create,
    .generate = flat_generate,
    .destroy = flat_destroy,
};

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    return index == 0 ? &probe : NULL;
}
