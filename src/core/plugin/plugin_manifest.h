/* plugin_manifest.h — the manifest beside a plugin module: `NAME.sylva-plugin` beside
 * `NAME.so`, a short text file naming each plugin the module provides, its kind and the ABI
 * version it was built against. The host reads it to choose and check a module without opening
 * it: a module whose manifest declares another ABI major is refused before any of its code (its
 * constructors included) runs. The build writes it (`sylva plugins --manifest NAME.so`) from the
 * module's own descriptors; the host compares the two when it opens the module.
 *
 *   # comments and blank lines are ignored
 *   sylva-plugin-manifest 1
 *   plugin tree_vessel tree 1.1
 *
 * One `plugin NAME KIND MAJOR.MINOR` line per descriptor, in the module's index order.
 */
#ifndef SYLVA_PLUGIN_MANIFEST_H
#define SYLVA_PLUGIN_MANIFEST_H

#include <stdint.h>

#include "sylva/plugin.h"
#include "util/err.h"

#define PLUGIN_MANIFEST_SUFFIX ".sylva-plugin"
#define PLUGIN_MANIFEST_MAX_PLUGINS 64 /* descriptors in one module (the registry's bound too) */
#define PLUGIN_MANIFEST_MAX_BYTES 65536

typedef struct manifest_plugin {
    char name[64];          /* as declared: at most PLUGIN_NAME_MAX bytes */
    sylva_kind kind;        /* 0 when the manifest says "unknown" */
    uint32_t abi_major, abi_minor;
} manifest_plugin;

typedef struct plugin_manifest {
    uint32_t n;
    manifest_plugin plugin[PLUGIN_MANIFEST_MAX_PLUGINS];
} plugin_manifest;

/* The manifest path of `module` ("dir/NAME.so" -> "dir/NAME.sylva-plugin") into buf. Returns 0,
 * or -1 when `module` does not end in ".so" or the path does not fit. */
int plugin_manifest_path(const char *module, char *buf, size_t cap);

/* Reads the manifest at `path`. Returns 1 when read, 0 when there is none (no such file), -1
 * when it cannot be used, with err saying "path:line: what is wrong". A path that is not a
 * regular file is refused without being opened. */
int plugin_manifest_read(const char *path, plugin_manifest *m, err_buf *err);

/* 1 when the manifest declares a plugin called `name`. */
int plugin_manifest_declares(const plugin_manifest *m, const char *name);

/* Opens `module` (running its constructors and sylva_plugin_get: this is a build step), reads
 * its descriptors and writes its manifest beside it, whole or not at all. Returns 0, or -1 with
 * err naming the module and what could not be read. */
int plugin_manifest_write(const char *module, err_buf *err);

#endif
