/* plugin_names.h — the names the plugin host gives and accepts: a well-formed plugin, parameter
 * or section name ([a-z][a-z0-9_]*, at most PLUGIN_NAME_MAX bytes) and the name of each plugin
 * kind. Shared by the registry (plugin_host.h) and the manifest beside a module
 * (plugin_manifest.h), which checks a declared name before any module is opened. */
#ifndef SYLVA_PLUGIN_NAMES_H
#define SYLVA_PLUGIN_NAMES_H

#include "sylva/plugin.h"

/* 1 when `name` is a well-formed plugin, parameter or section name: [a-z][a-z0-9_]*, at most
 * PLUGIN_NAME_MAX bytes; 0 otherwise (NULL included). */
#define PLUGIN_NAME_MAX 63
int plugin_name_is_valid(const char *name);

const char *plugin_kind_name(sylva_kind kind); /* "terrain", "tree", "ecology", "unknown" */

#endif
