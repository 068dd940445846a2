/* plugin_host.h — finding, loading and checking plugins.
 *
 * A registry holds every plugin found in the search path: each folder of SYLVA_PLUGIN_PATH
 * (colon-separated), then the build tree's plugin folder, then the install folder; the first
 * folder providing a name wins. Each module is dlopen()ed and its entry point
 * `sylva_plugin_get` called for descriptors; each descriptor is checked (ABI major, struct
 * sizes, name, kind, schema well-formedness, operations present) before it is listed. A module
 * or descriptor that fails a check is kept as a `plugin_problem` whose sentence names the file,
 * the symbol where one is involved, and the reason — it is never fatal to the host.
 *
 * Ownership: the registry owns the module handles (closed by plugin_registry_free) and the
 * problem list, and a copy of each accepted descriptor (zero-filled past the plugin's `size`,
 * so every field can be read); strings in them point into the modules and stay valid until then.
 */
#ifndef SYLVA_PLUGIN_HOST_H
#define SYLVA_PLUGIN_HOST_H

#include <stdio.h>

#include "sylva/plugin.h"
#include "util/err.h"

/* Keys the host owns inside plugin blocks; a plugin schema may not use them (the ecology
 * plugin's species_section name is reserved as well). NULL-terminated. */
extern const char *const plugin_reserved_keys[];

typedef struct loaded_plugin {
    const sylva_plugin *desc;
    const char *file;         /* module path (owned by the registry) */
} loaded_plugin;

typedef struct plugin_problem {
    const char *file;         /* module path */
    const char *message;      /* "file: symbol: reason" sentence (owned by the registry) */
} plugin_problem;

typedef struct plugin_registry plugin_registry;

/* Scans the default search path (see above). Never fails for a bad module: it is recorded as a
 * problem. Returns NULL only when memory runs out (err set). */
plugin_registry *plugin_registry_open(err_buf *err);
/* Scans exactly the given folders (for tests), colon-separated. */
plugin_registry *plugin_registry_open_path(const char *folders, err_buf *err);
/* Loads one module file explicitly; returns 0, or -1 with err naming file, symbol and reason
 * (the problem is also recorded). */
int plugin_registry_add_file(plugin_registry *reg, const char *file, err_buf *err);
void plugin_registry_free(plugin_registry *reg); /* accepts NULL */

uint32_t plugin_registry_count(const plugin_registry *reg);
const loaded_plugin *plugin_registry_at(const plugin_registry *reg, uint32_t i);
uint32_t plugin_registry_problem_count(const plugin_registry *reg);
const plugin_problem *plugin_registry_problem_at(const plugin_registry *reg, uint32_t i);

/* The plugin called `name`, or NULL. When kind != 0 and the plugin has another kind, returns
 * NULL and sets err saying which kind it has. When no plugin has the name, err lists the
 * plugins of that kind and suggests the nearest name. */
const loaded_plugin *plugin_registry_find(const plugin_registry *reg, const char *name,
                                          sylva_kind kind, err_buf *err);

/* Checks a schema table (used for plugin descriptors and for the host's own sections):
 * names well-formed and unique, types known, defaults inside ranges, enums with choices,
 * groups with members. Returns 0 or -1 with err naming the parameter and the reason. */
int plugin_schema_check(const sylva_param_spec *spec, uint32_t n, err_buf *err);

/* Prints a schema for `sylva plugins --describe` (one line a parameter, nested groups
 * indented): name, type, default, range, unit, help. */
void plugin_schema_print(FILE *out, const sylva_param_spec *spec, uint32_t n, int indent);

const char *plugin_kind_name(sylva_kind kind); /* "terrain", "tree", "ecology", "unknown" */

/* The folders the registry searched, most important first, as they were given (a folder named
 * twice is listed once). Strings owned by the registry. */
uint32_t plugin_registry_folder_count(const plugin_registry *reg);
const char *plugin_registry_folder_at(const plugin_registry *reg, uint32_t i);

/* 1 when `name` is a well-formed plugin, parameter or section name: [a-z][a-z0-9_]*, at most
 * PLUGIN_NAME_MAX bytes; 0 otherwise (NULL included). */
#define PLUGIN_NAME_MAX 63
int plugin_name_is_valid(const char *name);

const char *plugin_param_type_name(sylva_ptype type); /* "int", "real", ..., "unknown" */

#endif
