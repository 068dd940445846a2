/* plugin_host.h — finding, loading and checking plugins.
 *
 * A registry holds every plugin module found in the search path: each folder of
 * SYLVA_PLUGIN_PATH (colon-separated), then the build tree's plugin folder (only for a program
 * that runs from the build tree, plugin_running_from_build_tree), then the install folder; the
 * first module providing a name wins. Opening the registry lists the modules and reads the
 * manifest beside each (plugin_manifest.h) but opens none: plugin_registry_find opens the
 * module that declares the name on first use, plugin_registry_load_all opens every one (for a
 * listing). An opened module's entry point `sylva_plugin_get` is called for descriptors; each
 * descriptor is checked (ABI major, struct sizes, name, kind, schema well-formedness, presets,
 * operations present, agreement with the manifest) before it is listed. A module or descriptor
 * that fails a check is kept as a `plugin_problem` whose sentence names the file, the symbol
 * where one is involved, and the reason — it is never fatal to the host.
 *
 * Ownership: the registry owns the module handles (closed by plugin_registry_free) and the
 * problem list, and a copy of each accepted descriptor (zero-filled past the plugin's `size`,
 * so every field can be read); strings in them point into the modules and stay valid until then.
 */
#ifndef SYLVA_PLUGIN_HOST_H
#define SYLVA_PLUGIN_HOST_H

#include <stdio.h>

#include "plugin/plugin_names.h" /* names and kinds, with the descriptors of sylva/plugin.h */
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

/* Scans the default search path (see above), opening no module. Never fails for a bad module:
 * it is recorded as a problem. Returns NULL only when memory runs out (err set). */
plugin_registry *plugin_registry_open(err_buf *err);
/* Scans exactly the given folders (for tests), colon-separated. */
plugin_registry *plugin_registry_open_path(const char *folders, err_buf *err);
/* Opens every module not opened yet, in search order, so that the lists below hold every
 * plugin and problem of the search path. Returns 0, or -1 when memory runs out (err set). */
int plugin_registry_load_all(plugin_registry *reg, err_buf *err);
/* Loads one module file explicitly (checked against its manifest when it has one); returns 0,
 * or -1 with err naming file, symbol and reason (the problem is also recorded). */
int plugin_registry_add_file(plugin_registry *reg, const char *file, err_buf *err);
void plugin_registry_free(plugin_registry *reg); /* accepts NULL */

/* 1 when this program's executable lies inside the build tree it was built in (SYLVA_BUILD_ROOT),
 * so that the build tree's plugin folder belongs in its search path; 0 for an installed copy. */
int plugin_running_from_build_tree(void);

/* Modules opened so far (dlopen()ed, whether or not they were accepted). */
uint32_t plugin_registry_opened_count(const plugin_registry *reg);

/* The plugins and problems found so far: every one after plugin_registry_load_all. */
uint32_t plugin_registry_count(const plugin_registry *reg);
const loaded_plugin *plugin_registry_at(const plugin_registry *reg, uint32_t i);
uint32_t plugin_registry_problem_count(const plugin_registry *reg);
const plugin_problem *plugin_registry_problem_at(const plugin_registry *reg, uint32_t i);

/* The plugin called `name`, or NULL. Opens the module that provides it on first use (and, when
 * no manifest declares the name, the modules without a manifest, in search order): a registry
 * is a cache of the search path and changes inside even through a const pointer; it is not for
 * use from several threads at once. When kind != 0 and the plugin has another kind, returns
 * NULL and sets err saying which kind it has. When no plugin has the name, every module is
 * opened and err lists the plugins of that kind and suggests the nearest name. A loaded_plugin
 * it (or plugin_registry_at) returns stays valid until plugin_registry_free, whatever is opened
 * later. */
const loaded_plugin *plugin_registry_find(const plugin_registry *reg, const char *name,
                                          sylva_kind kind, err_buf *err);

/* Checks a schema table (used for plugin descriptors and for the host's own sections):
 * names well-formed and unique, types known, defaults inside ranges, enums with choices,
 * groups with members. Returns 0 or -1 with err naming the parameter and the reason. */
int plugin_schema_check(const sylva_param_spec *spec, uint32_t n, err_buf *err);

/* Prints a schema for `sylva plugins --describe` (one line a parameter, nested groups
 * indented): name, type, default, range, unit, help. */
void plugin_schema_print(FILE *out, const sylva_param_spec *spec, uint32_t n, int indent);

/* Checks a descriptor's presets (ABI 1.1) against its schema: preset_param an ENUM of the
 * schema, one preset per choice in the choices' order, every value naming a parameter of the
 * schema once, of its type and inside its range. Returns 0 (also when there are none) or -1
 * with err naming the preset, the parameter and the reason. */
int plugin_presets_check(const sylva_plugin *d, err_buf *err);

/* Prints each preset for `sylva plugins --describe`: its name and help, then one line per value
 * it sets (name, value, unit). Prints nothing when the descriptor has no presets. */
void plugin_presets_print(FILE *out, const sylva_plugin *d, int indent);

/* The folders the registry searched, most important first, as they were given (a folder named
 * twice is listed once). Strings owned by the registry. */
uint32_t plugin_registry_folder_count(const plugin_registry *reg);
const char *plugin_registry_folder_at(const plugin_registry *reg, uint32_t i);

const char *plugin_param_type_name(sylva_ptype type); /* "int", "real", ..., "unknown" */

/* 1 when v (not NaN) lies inside the spec's range flags, 0 otherwise. */
int plugin_value_in_range(const sylva_param_spec *p, double v);
/* A number for people: whole numbers in full (2^53 as 9007199254740992), others with up to ten
 * significant digits. Returns buf. */
const char *plugin_number_format(char buf[32], double v);

#endif
