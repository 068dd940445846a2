/* plugin_host.c — the plugin registry: the search path, loading modules, checking descriptors.
 *
 * Folders are searched most important first (SYLVA_PLUGIN_PATH, the build tree when this
 * program runs from it, the install folder); inside a folder, *.so files are taken in byte order
 * of their names so that the outcome never depends on the file system. Scanning lists the
 * modules and reads the manifest beside each (plugin_manifest.h) but opens none: a module is
 * opened when a plugin it declares is first looked up (or when everything is listed), and a
 * module whose manifest declares another ABI major is never opened. A module without a manifest
 * can only be checked once open, so a lookup opens such modules in search order until the name
 * turns up. A module is opened with RTLD_NOW | RTLD_LOCAL so a missing symbol fails here, not in
 * the middle of a render, and two modules cannot see each other's symbols. Every descriptor is
 * checked before it is listed; whatever fails becomes a problem sentence and never stops the
 * scan. Only `sylva_plugin_get` runs in the plugin.
 *
 * The registry keeps a host-side copy of each accepted descriptor, zero-filled past the size
 * the plugin declared, so the rest of the host may read every field the host knows.
 */
#include <dirent.h>
#include <dlfcn.h>
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "plugin/plugin_host.h"
#include "plugin/plugin_manifest.h"
#include "util/arena.h"
#include "util/build_tree.h"
#include "util/edit_distance.h"

/* A module returning descriptors for this many indices without a NULL is refused whole. */
#define REGISTRY_MAX_DESCRIPTORS PLUGIN_MANIFEST_MAX_PLUGINS

#define FIELD_END(type, field) SYLVA_FIELD_END(type, field)

/* Bytes of sylva_plugin that each ABI minor defines: a descriptor that declares minor m must be
 * at least descriptor_bytes[m] long. A minor that appends fields appends an entry here. */
static const size_t descriptor_bytes[SYLVA_ABI_MINOR + 1] = {
    SYLVA_PLUGIN_SIZE_1_0,
    SYLVA_PLUGIN_SIZE_1_1,
    SYLVA_PLUGIN_SIZE_1_2,
    SYLVA_PLUGIN_SIZE_1_3,
    SYLVA_PLUGIN_SIZE_1_4,
    SYLVA_PLUGIN_SIZE_1_5,
    SYLVA_PLUGIN_SIZE_1_6,
    SYLVA_PLUGIN_SIZE_1_7,
};

/* One module file of the search path, in search order. */
typedef struct module_entry {
    const char *file;                 /* absolute path (owned by the registry's arena) */
    const plugin_manifest *manifest;  /* the manifest beside it (arena), or NULL: none */
    const char *manifest_error;       /* why the manifest cannot be used (arena), or NULL */
    enum { MODULE_LISTED, MODULE_OPENED, MODULE_REFUSED } state; /* REFUSED: by its manifest,
                                                                     never opened */
} module_entry;

typedef struct search_folder {
    const char *given; /* as named in the search path */
    const char *key;   /* its real path, or the text as given when it does not resolve */
} search_folder;

typedef struct registry_problem {
    plugin_problem pub;
    const char *plugin; /* the refused plugin's name when it could be read, else NULL */
} registry_problem;

struct plugin_registry {
    arena *strings;                 /* owns every string and descriptor copy below */
    loaded_plugin **plugins;        /* malloc'ed array of entries in the arena: a pointer handed
                                       out stays valid while later lookups open more modules */
    uint32_t n_plugins, cap_plugins;
    registry_problem *problems;     /* malloc'ed array */
    uint32_t n_problems, cap_problems;
    void **modules;                 /* dlopen handles with an accepted descriptor; dlclose'd */
    uint32_t n_modules, cap_modules;
    search_folder *folders;         /* malloc'ed array, in order of precedence */
    uint32_t n_folders, cap_folders;
    module_entry *entries;          /* malloc'ed array: every module found, in search order */
    uint32_t n_entries, cap_entries;
};

/* Makes room for `need` elements; returns 0 or -1 when memory runs out. */
static int grow(void **array, uint32_t *cap, uint32_t need, size_t elem)
{
    if (need <= *cap) return 0;
    uint32_t c = *cap ? *cap : 8;
    while (c < need) c *= 2;
    void *p = realloc(*array, (size_t)c * elem);
    if (!p) return -1;
    *array = p;
    *cap = c;
    return 0;
}

/* Records a problem. Returns 1 (recorded) or -1 when memory runs out. */
static int SYLVA_PRINTF(4, 5) record_problem(plugin_registry *reg, const char *file,
                                             const char *plugin, const char *fmt, ...)
{
    char msg[ERR_MSG_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (grow((void **)&reg->problems, &reg->cap_problems, reg->n_problems + 1,
             sizeof *reg->problems))
        return -1;
    registry_problem *p = &reg->problems[reg->n_problems];
    p->pub.file = file;
    p->pub.message = arena_strdup(reg->strings, msg);
    p->plugin = plugin ? arena_strdup(reg->strings, plugin) : NULL;
    if (!p->pub.message || (plugin && !p->plugin)) return -1;
    reg->n_problems++;
    return 1;
}

static const loaded_plugin *registry_lookup(const plugin_registry *reg, const char *name)
{
    for (uint32_t i = 0; i < reg->n_plugins; i++)
        if (!strcmp(reg->plugins[i]->desc->name, name)) return reg->plugins[i];
    return NULL;
}

/* --------------------------------------------------------------------------------------------
 * Descriptors
 */

const char *const plugin_reserved_keys[] = {"plugin", "material", "variants", "shape",   "grid",
                                            "origin", "spacing",  "include",  "phenology", NULL};

/* The host key `name` would take in a plugin block, or NULL when it is free. */
static const char *reserved_key(const char *name)
{
    for (const char *const *r = plugin_reserved_keys; *r; r++)
        if (!strcmp(*r, name)) return *r;
    return NULL;
}

/* "plugin, material, ..." — the reserved keys, for messages. */
static void reserved_key_list(char *buf, size_t cap)
{
    size_t len = 0;
    buf[0] = '\0';
    for (const char *const *r = plugin_reserved_keys; *r && len < cap; r++) {
        int w = snprintf(buf + len, cap - len, "%s%s", r == plugin_reserved_keys ? "" : ", ", *r);
        if (w < 0) break;
        len += (size_t)w;
    }
}

/* What a descriptor's fields say is wrong, or "" when nothing is. `d` is the host-side copy. */
static void descriptor_fault(const sylva_plugin *d, char *why, size_t cap)
{
    err_buf e;
    why[0] = '\0';
    if ((int)d->kind < SYLVA_KIND_TERRAIN || (int)d->kind > SYLVA_KIND_ECOLOGY) {
        snprintf(why, cap, "unknown kind %d; kinds are SYLVA_KIND_TERRAIN (1), SYLVA_KIND_TREE "
                 "(2) and SYLVA_KIND_ECOLOGY (3)", (int)d->kind);
        return;
    }
    if (!d->summary || !d->summary[0] || strchr(d->summary, '\n')) {
        snprintf(why, cap, "the summary is %s; give one line saying what the plugin makes",
                 !d->summary ? "NULL" : !d->summary[0] ? "empty" : "more than one line");
        return;
    }
    if (!d->version || !d->version[0]) {
        snprintf(why, cap, "the version is %s; give the plugin's own version, e.g. \"1.0\"",
                 d->version ? "empty" : "NULL");
        return;
    }
    if (!d->create || !d->generate || !d->destroy) {
        snprintf(why, cap, "the operation %s is NULL; create, generate and destroy are all "
                 "required", !d->create ? "create" : !d->generate ? "generate" : "destroy");
        return;
    }
    if (plugin_schema_check(d->params, d->n_params, &e)) {
        snprintf(why, cap, "params: %s", e.msg);
        return;
    }
    char keys[256];
    reserved_key_list(keys, sizeof keys);
    for (uint32_t k = 0; k < d->n_params; k++)
        if (reserved_key(d->params[k].name)) {
            snprintf(why, cap, "params: parameter '%s' takes a key the host keeps for itself in "
                     "a plugin's block (%s); rename it", d->params[k].name, keys);
            return;
        }
    if (plugin_presets_check(d, &e)) {
        snprintf(why, cap, "presets: %s", e.msg);
        return;
    }
    int has_species = d->species_section || d->species_params || d->n_species_params;
    if (d->kind != SYLVA_KIND_ECOLOGY) {
        if (has_species)
            snprintf(why, cap, "a %s plugin has no species section; species_section and "
                     "species_params are for ecology plugins", plugin_kind_name(d->kind));
        return;
    }
    if (!has_species) return;
    if (!plugin_name_is_valid(d->species_section)) {
        snprintf(why, cap, "species_section %s%.*s%s is not a valid section name: a lowercase "
                 "letter, then lowercase letters, digits or '_'",
                 d->species_section ? "\"" : "", PLUGIN_NAME_MAX + 1,
                 d->species_section ? d->species_section : "NULL", d->species_section ? "\"" : "");
        return;
    }
    if (reserved_key(d->species_section)) {
        snprintf(why, cap, "species_section \"%s\" is a key the host keeps for itself in a "
                 "species (%s); choose another", d->species_section, keys);
        return;
    }
    if (plugin_schema_check(d->species_params, d->n_species_params, &e))
        snprintf(why, cap, "species_params: %s", e.msg);
}

/* Checks descriptor `index` of `file` and lists it. `taken` holds the names this module
 * already declared (n_taken of them). Returns 1 listed, 0 refused (problem recorded), -1 out of
 * memory. */
static int registry_add_descriptor(plugin_registry *reg, const char *file, uint32_t index,
                                   const sylva_plugin *raw, const manifest_plugin *expect,
                                   const char **taken, uint32_t n_taken)
{
    const char *sym = SYLVA_PLUGIN_ENTRY;
    if (raw->size < FIELD_END(sylva_plugin, abi_minor))
        return record_problem(reg, file, NULL, "%s: %s(%u): the descriptor declares size %u, too "
                              "small to hold its ABI version; set size = sizeof(sylva_plugin)",
                              file, sym, index, raw->size) < 0 ? -1 : 0;
    if (raw->abi_major != SYLVA_ABI_MAJOR)
        return record_problem(reg, file, NULL, "%s: %s(%u): built against sylva plugin ABI %u.%u, "
                              "this host speaks %d.%d; rebuild the plugin", file, sym, index,
                              raw->abi_major, raw->abi_minor, SYLVA_ABI_MAJOR, SYLVA_ABI_MINOR)
                       < 0 ? -1 : 0;
    uint32_t minor = raw->abi_minor; /* a newer minor only appends: read what this host knows */
    if (minor > SYLVA_ABI_MINOR) minor = SYLVA_ABI_MINOR;
    if (raw->size < descriptor_bytes[minor])
        return record_problem(reg, file, NULL, "%s: %s(%u): the descriptor declares size %u, "
                              "but sylva plugin ABI %d.%u defines %zu bytes; set size = "
                              "sizeof(sylva_plugin) and rebuild the plugin", file, sym, index,
                              raw->size, SYLVA_ABI_MAJOR, minor, descriptor_bytes[minor])
                       < 0 ? -1 : 0;

    sylva_plugin d; /* host-side view: what the plugin declared, zeros past its size */
    memset(&d, 0, sizeof d);
    memcpy(&d, raw, raw->size < sizeof d ? raw->size : sizeof d);
    d.size = sizeof d;

    if (d.param_spec_size != sizeof(sylva_param_spec))
        return record_problem(reg, file, NULL, "%s: %s(%u): param_spec_size is %u bytes, but this "
                              "host's sylva_param_spec is %zu bytes; rebuild the plugin against "
                              "this host's sylva/plugin.h", file, sym, index, d.param_spec_size,
                              sizeof(sylva_param_spec)) < 0 ? -1 : 0;
    if (!plugin_name_is_valid(d.name))
        return record_problem(reg, file, NULL, "%s: %s(%u): the plugin name %s%.*s%s is not valid: "
                              "a lowercase letter, then lowercase letters, digits or '_', at "
                              "most %d bytes", file, sym, index, d.name ? "\"" : "",
                              PLUGIN_NAME_MAX + 1, d.name ? d.name : "NULL", d.name ? "\"" : "",
                              PLUGIN_NAME_MAX) < 0 ? -1 : 0;
    if (expect && (strcmp(expect->name, d.name) || expect->kind != d.kind ||
                   expect->abi_major != raw->abi_major || expect->abi_minor != raw->abi_minor))
        return record_problem(reg, file, d.name, "%s: %s(%u): plugin '%s' (%s, ABI %u.%u) does "
                              "not match its manifest, which says '%s' (%s, ABI %u.%u); rewrite "
                              "the manifest with `sylva plugins --manifest %s`", file, sym, index,
                              d.name, plugin_kind_name(d.kind), raw->abi_major, raw->abi_minor,
                              expect->name, plugin_kind_name(expect->kind), expect->abi_major,
                              expect->abi_minor, file) < 0 ? -1 : 0;
    for (uint32_t k = 0; k < n_taken; k++)
        if (!strcmp(taken[k], d.name))
            return record_problem(reg, file, d.name, "%s: %s(%u): plugin '%s': the module already "
                                  "declares a plugin of this name; names must be unique", file,
                                  sym, index, d.name) < 0 ? -1 : 0;

    char why[ERR_MSG_MAX];
    descriptor_fault(&d, why, sizeof why);
    if (why[0])
        return record_problem(reg, file, d.name, "%s: %s(%u): plugin '%s': %s", file, sym, index,
                              d.name, why) < 0 ? -1 : 0;

    const loaded_plugin *earlier = registry_lookup(reg, d.name);
    if (earlier)
        return record_problem(reg, file, NULL, "%s: %s(%u): plugin '%s' is ignored: %s, earlier "
                              "in the search path, already provides it", file, sym, index, d.name,
                              earlier->file) < 0 ? -1 : 0;

    sylva_plugin *copy = arena_alloc(reg->strings, sizeof *copy);
    loaded_plugin *lp = arena_alloc(reg->strings, sizeof *lp);
    if (!copy || !lp) return -1;
    *copy = d;
    *lp = (loaded_plugin){copy, file};
    if (grow((void **)&reg->plugins, &reg->cap_plugins, reg->n_plugins + 1, sizeof *reg->plugins))
        return -1;
    reg->plugins[reg->n_plugins++] = lp;
    return 1;
}

/* --------------------------------------------------------------------------------------------
 * Modules
 */

/* Loads `file` (an absolute path owned by the registry) and checks its descriptors against
 * `manifest` (NULL: none). Returns 0, or -1 when memory runs out; everything else that goes
 * wrong is recorded as a problem. */
static int registry_load_module(plugin_registry *reg, const char *file,
                                const plugin_manifest *manifest)
{
    dlerror();
    void *handle = dlopen(file, RTLD_NOW | RTLD_LOCAL); /* owned here until kept or closed */
    if (!handle) {
        const char *why = dlerror();
        return record_problem(reg, file, NULL, "%s: cannot load shared library: %s", file,
                              why ? why : "dlopen failed without a reason") < 0 ? -1 : 0;
    }
    dlerror();
    void *entry = dlsym(handle, SYLVA_PLUGIN_ENTRY);
    if (!entry) {
        dlclose(handle);
        return record_problem(reg, file, NULL, "no entry point [%s] in shared library [%s]; a "
                              "plugin exports `SYLVA_EXPORT const sylva_plugin *%s(uint32_t "
                              "index)`", SYLVA_PLUGIN_ENTRY, file, SYLVA_PLUGIN_ENTRY)
                       < 0 ? -1 : 0;
    }
    sylva_plugin_get_fn get = (sylva_plugin_get_fn)entry;

    const sylva_plugin *found[REGISTRY_MAX_DESCRIPTORS];
    uint32_t n = 0;
    while (n < REGISTRY_MAX_DESCRIPTORS && (found[n] = get(n)) != NULL) n++;
    int rc = 0;
    if (n == REGISTRY_MAX_DESCRIPTORS && get(n) != NULL) {
        rc = record_problem(reg, file, NULL, "%s: %s: returned a descriptor for every index from "
                            "0 to %d; it must return NULL past its last descriptor (a module "
                            "holds at most %d)", file, SYLVA_PLUGIN_ENTRY,
                            REGISTRY_MAX_DESCRIPTORS, REGISTRY_MAX_DESCRIPTORS);
        n = 0;
    } else if (n == 0) {
        rc = record_problem(reg, file, NULL, "%s: %s(0) returned NULL: the module provides no "
                            "plugin", file, SYLVA_PLUGIN_ENTRY);
    } else if (manifest && manifest->n != n) {
        rc = record_problem(reg, file, NULL, "%s: the module provides %u plugin%s, its manifest "
                            "names %u; rewrite the manifest with `sylva plugins --manifest %s`",
                            file, n, n == 1 ? "" : "s", manifest->n, file);
        n = 0;
    }

    const char *taken[REGISTRY_MAX_DESCRIPTORS]; /* names this module declared, validated */
    uint32_t n_taken = 0, listed = 0;
    for (uint32_t i = 0; i < n && rc >= 0; i++) {
        int r = registry_add_descriptor(reg, file, i, found[i],
                                        manifest ? &manifest->plugin[i] : NULL, taken, n_taken);
        if (r < 0) rc = -1;
        if (r > 0) {
            listed++;
            taken[n_taken++] = reg->plugins[reg->n_plugins - 1]->desc->name;
        } else if (r == 0 && reg->problems[reg->n_problems - 1].plugin) {
            taken[n_taken++] = reg->problems[reg->n_problems - 1].plugin;
        }
    }
    if (rc >= 0 && listed) {
        if (grow((void **)&reg->modules, &reg->cap_modules, reg->n_modules + 1,
                 sizeof *reg->modules) == 0) {
            reg->modules[reg->n_modules++] = handle;
            return 0;
        }
        rc = -1;
    }
    /* Nothing listed points into the module unless it was kept above; drop what was listed
     * from it when memory ran out so no descriptor outlives its code. */
    if (rc < 0) {
        while (reg->n_plugins && reg->plugins[reg->n_plugins - 1]->file == file) reg->n_plugins--;
    }
    dlclose(handle);
    return rc < 0 ? -1 : 0;
}

/* Lists module `file` (absolute, owned by the registry) without opening it, with the manifest
 * beside it read. Returns 0, or -1 when memory runs out. */
static int registry_list_module(plugin_registry *reg, const char *file)
{
    if (grow((void **)&reg->entries, &reg->cap_entries, reg->n_entries + 1, sizeof *reg->entries))
        return -1;
    module_entry *e = &reg->entries[reg->n_entries++];
    *e = (module_entry){file, NULL, NULL, MODULE_LISTED};
    char path[4096];
    if (plugin_manifest_path(file, path, sizeof path)) return 0;
    plugin_manifest *m = arena_alloc(reg->strings, sizeof *m);
    if (!m) return -1;
    err_buf err;
    int r = plugin_manifest_read(path, m, &err);
    if (r > 0) e->manifest = m;
    if (r < 0 && !(e->manifest_error = arena_strdup(reg->strings, err.msg))) return -1;
    return 0;
}

/* Refuses entry e for its manifest (recording why) without opening it: a manifest that cannot
 * be used, or one that declares no plugin of this host's ABI major. Returns 1 refused, 0 not,
 * -1 when memory runs out. */
static int registry_refuse_by_manifest(plugin_registry *reg, module_entry *e)
{
    if (e->manifest_error)
        return record_problem(reg, e->file, NULL, "%s: not opened: %s", e->file,
                              e->manifest_error);
    const plugin_manifest *m = e->manifest;
    uint32_t usable = 0;
    for (uint32_t i = 0; m && i < m->n; i++) usable += m->plugin[i].abi_major == SYLVA_ABI_MAJOR;
    if (!m || usable) return 0;
    char path[4096];
    plugin_manifest_path(e->file, path, sizeof path);
    for (uint32_t i = 0; i < m->n; i++)
        if (record_problem(reg, e->file, m->plugin[i].name, "%s: not opened: its manifest %s says "
                           "plugin '%s' is built against sylva plugin ABI %u.%u, this host speaks "
                           "%d.%d; rebuild the plugin", e->file, path, m->plugin[i].name,
                           m->plugin[i].abi_major, m->plugin[i].abi_minor, SYLVA_ABI_MAJOR,
                           SYLVA_ABI_MINOR) < 0)
            return -1;
    return 1;
}

/* Opens entry i if it is not open yet, unless its manifest refuses it. Returns 0, or -1 when
 * memory runs out. */
static int registry_open_entry(plugin_registry *reg, uint32_t i)
{
    module_entry *e = &reg->entries[i];
    if (e->state != MODULE_LISTED) return 0;
    int refused = registry_refuse_by_manifest(reg, e);
    if (refused) {
        e->state = MODULE_REFUSED;
        return refused < 0 ? -1 : 0;
    }
    e->state = MODULE_OPENED;
    return registry_load_module(reg, e->file, e->manifest);
}

static int name_is_module(const struct dirent *e)
{
    size_t n = strlen(e->d_name);
    return e->d_name[0] != '.' && n > 3 && !strcmp(e->d_name + n - 3, ".so");
}

static int by_name(const struct dirent **a, const struct dirent **b)
{
    return strcmp((*a)->d_name, (*b)->d_name);
}

/* Scans one folder. A folder that does not exist is skipped quietly; one that cannot be read is
 * a problem. Returns 0, or -1 when memory runs out. */
static int registry_scan_folder(plugin_registry *reg, const char *folder)
{
    char *real = realpath(folder, NULL); /* malloc'ed by libc, freed below */
    const char *key = real ? real : folder;
    for (uint32_t i = 0; i < reg->n_folders; i++)
        if (!strcmp(reg->folders[i].key, key)) {
            free(real);
            return 0;
        }
    const char *given = arena_strdup(reg->strings, folder);
    const char *stored_key = arena_strdup(reg->strings, key);
    free(real);
    if (!given || !stored_key ||
        grow((void **)&reg->folders, &reg->cap_folders, reg->n_folders + 1, sizeof *reg->folders))
        return -1;
    reg->folders[reg->n_folders++] = (search_folder){given, stored_key};

    struct stat st;
    if (stat(stored_key, &st) != 0) return 0; /* absent: nothing to find there */
    if (!S_ISDIR(st.st_mode))
        return record_problem(reg, given, NULL, "%s: the plugin search path names this, but it "
                              "is not a folder", given) < 0 ? -1 : 0;

    struct dirent **entries = NULL; /* malloc'ed by scandir, each entry and the array freed below */
    errno = 0;
    int n = scandir(stored_key, &entries, name_is_module, by_name);
    if (n < 0) {
        if (errno == ENOMEM) return -1;
        return record_problem(reg, given, NULL, "%s: cannot read the plugin folder: %s", given,
                              strerror(errno)) < 0 ? -1 : 0;
    }
    int rc = 0;
    for (int i = 0; i < n; i++) {
        if (rc == 0) {
            size_t len = strlen(stored_key) + 1 + strlen(entries[i]->d_name) + 1;
            char *path = arena_alloc(reg->strings, len);
            if (!path) {
                rc = -1;
            } else {
                snprintf(path, len, "%s/%s", stored_key, entries[i]->d_name);
                if (stat(path, &st) == 0 && S_ISREG(st.st_mode)) rc = registry_list_module(reg, path);
            }
        }
        free(entries[i]);
    }
    free(entries);
    return rc;
}

/* Scans each folder of a colon-separated list, in order; empty entries are skipped. */
static int registry_scan_list(plugin_registry *reg, const char *list)
{
    const char *p = list;
    while (p && *p) {
        const char *colon = strchr(p, ':');
        size_t len = colon ? (size_t)(colon - p) : strlen(p);
        if (len) {
            char *folder = arena_strndup(reg->strings, p, len);
            if (!folder || registry_scan_folder(reg, folder)) return -1;
        }
        p = colon ? colon + 1 : NULL;
    }
    return 0;
}

static plugin_registry *registry_new(err_buf *err)
{
    plugin_registry *reg = calloc(1, sizeof *reg); /* owned by the caller: plugin_registry_free */
    if (reg) reg->strings = arena_new();
    if (!reg || !reg->strings) {
        free(reg);
        err_nomem(err, "out of memory while creating the plugin registry");
        return NULL;
    }
    return reg;
}

static plugin_registry *registry_out_of_memory(plugin_registry *reg, err_buf *err)
{
    plugin_registry_free(reg);
    err_nomem(err, "out of memory while scanning for plugins");
    return NULL;
}

int plugin_running_from_build_tree(void)
{
    return build_tree_running();
}

plugin_registry *plugin_registry_open(err_buf *err)
{
    plugin_registry *reg = registry_new(err);
    if (!reg) return NULL;
    if (registry_scan_list(reg, getenv("SYLVA_PLUGIN_PATH")) ||
        (plugin_running_from_build_tree() && registry_scan_folder(reg, SYLVA_PLUGIN_BUILD_DIR)) ||
        registry_scan_folder(reg, SYLVA_PLUGIN_INSTALL_DIR))
        return registry_out_of_memory(reg, err);
    return reg;
}

int plugin_registry_load_all(plugin_registry *reg, err_buf *err)
{
    for (uint32_t i = 0; reg && i < reg->n_entries; i++)
        if (registry_open_entry(reg, i))
            return err_nomem(err, "out of memory while loading the plugin module %s",
                           reg->entries[i].file);
    return 0;
}

uint32_t plugin_registry_opened_count(const plugin_registry *reg)
{
    uint32_t n = 0;
    for (uint32_t i = 0; reg && i < reg->n_entries; i++)
        n += reg->entries[i].state == MODULE_OPENED;
    return n;
}

plugin_registry *plugin_registry_open_path(const char *folders, err_buf *err)
{
    plugin_registry *reg = registry_new(err);
    if (!reg) return NULL;
    if (registry_scan_list(reg, folders)) return registry_out_of_memory(reg, err);
    return reg;
}

int plugin_registry_add_file(plugin_registry *reg, const char *file, err_buf *err)
{
    if (!reg || !file || !file[0])
        return err_set(err, "plugin_registry_add_file needs a registry and a module file name");
    uint32_t before = reg->n_problems;
    char *real = realpath(file, NULL); /* malloc'ed by libc, freed below */
    int rc;
    if (!real) {
        const char *given = arena_strdup(reg->strings, file);
        rc = given ? record_problem(reg, given, NULL, "%s: no shared library there: %s", given,
                                    strerror(errno))
                   : -1;
    } else {
        char *path = arena_strdup(reg->strings, real);
        free(real);
        rc = path ? registry_list_module(reg, path) : -1;
        if (rc == 0) rc = registry_open_entry(reg, reg->n_entries - 1);
    }
    if (rc < 0) return err_nomem(err, "out of memory while loading the plugin module %s", file);
    if (reg->n_problems > before) return err_set(err, "%s", reg->problems[before].pub.message);
    return 0;
}

void plugin_registry_free(plugin_registry *reg)
{
    if (!reg) return;
    for (uint32_t i = reg->n_modules; i-- > 0;) dlclose(reg->modules[i]);
    free(reg->modules);
    free(reg->plugins);
    free(reg->problems);
    free(reg->folders);
    free(reg->entries);
    arena_free(reg->strings);
    free(reg);
}

/* --------------------------------------------------------------------------------------------
 * Queries
 */

uint32_t plugin_registry_count(const plugin_registry *reg) { return reg ? reg->n_plugins : 0; }

const loaded_plugin *plugin_registry_at(const plugin_registry *reg, uint32_t i)
{
    return reg && i < reg->n_plugins ? reg->plugins[i] : NULL;
}

uint32_t plugin_registry_problem_count(const plugin_registry *reg)
{
    return reg ? reg->n_problems : 0;
}

const plugin_problem *plugin_registry_problem_at(const plugin_registry *reg, uint32_t i)
{
    return reg && i < reg->n_problems ? &reg->problems[i].pub : NULL;
}

uint32_t plugin_registry_folder_count(const plugin_registry *reg)
{
    return reg ? reg->n_folders : 0;
}

const char *plugin_registry_folder_at(const plugin_registry *reg, uint32_t i)
{
    return reg && i < reg->n_folders ? reg->folders[i].given : NULL;
}

/* Appends to err->msg, keeping it terminated; once full, later text is dropped. */
static void SYLVA_PRINTF(2, 3) err_append(err_buf *err, const char *fmt, ...)
{
    size_t len = strlen(err->msg);
    if (len + 1 >= sizeof err->msg) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->msg + len, sizeof err->msg - len, fmt, ap);
    va_end(ap);
}

/* ", the terrain plugins are: a, b" or ", no terrain plugin was found"; then the folders. */
static void err_append_inventory(err_buf *err, const plugin_registry *reg, sylva_kind kind)
{
    const char *kname = kind ? plugin_kind_name(kind) : NULL;
    uint32_t shown = 0;
    for (uint32_t i = 0; i < reg->n_plugins; i++) {
        const sylva_plugin *d = reg->plugins[i]->desc;
        if (kind && d->kind != kind) continue;
        if (shown == 0) err_append(err, "; the %s%splugins are: ", kname ? kname : "",
                                   kname ? " " : "");
        err_append(err, "%s%s", shown ? ", " : "", d->name);
        shown++;
    }
    if (shown == 0) {
        err_append(err, "; no %s%splugin was found in", kname ? kname : "", kname ? " " : "");
        for (uint32_t i = 0; i < reg->n_folders; i++)
            err_append(err, "%s %s", i ? "," : "", reg->folders[i].given);
        if (reg->n_folders == 0) err_append(err, " an empty search path");
        err_append(err, " (SYLVA_PLUGIN_PATH adds folders)");
    }
    if (reg->n_problems)
        err_append(err, "; %u problem%s came up while loading plugins (`sylva plugins` lists "
                   "them)", reg->n_problems, reg->n_problems == 1 ? "" : "s");
}

const loaded_plugin *plugin_registry_find(const plugin_registry *reg, const char *name,
                                          sylva_kind kind, err_buf *err)
{
    if (!reg || !name || !name[0]) {
        err_set(err, "no plugin name given; a scene names a plugin with `plugin: NAME`");
        return NULL;
    }
    const char *kname = kind ? plugin_kind_name(kind) : "";
    /* A registry is a cache of the search path: finding a plugin opens its module on first
     * use, so the registry changes inside even through a const pointer. */
    plugin_registry *cache = (plugin_registry *)reg;
    const loaded_plugin *lp = registry_lookup(reg, name);
    for (uint32_t i = 0; !lp && i < reg->n_entries; i++) {
        const module_entry *e = &reg->entries[i];
        if (e->state != MODULE_LISTED || (e->manifest && !plugin_manifest_declares(e->manifest, name)))
            continue;
        if (registry_open_entry(cache, i)) {
            err_nomem(err, "out of memory while loading the plugin module %s", e->file);
            return NULL;
        }
        lp = registry_lookup(reg, name);
    }
    if (!lp && plugin_registry_load_all(cache, err)) return NULL; /* for the sentence below */
    if (!lp) lp = registry_lookup(reg, name);
    if (lp && kind && lp->desc->kind != kind) {
        sylva_kind has = lp->desc->kind;
        if (plugin_registry_load_all(cache, err)) return NULL; /* the inventory lists them all */
        err_set(err, "plugin '%s' is %s %s plugin, not %s %s plugin", name,
                has == SYLVA_KIND_ECOLOGY ? "an" : "a", plugin_kind_name(has),
                kind == SYLVA_KIND_ECOLOGY ? "an" : "a", kname);
        err_append_inventory(err, reg, kind);
        return NULL;
    }
    if (lp) return lp;

    /* A refused plugin: by the name its descriptor gave, or else by a module named after it. */
    const registry_problem *refused = NULL;
    for (uint32_t i = 0; i < reg->n_problems && !refused; i++)
        if (reg->problems[i].plugin && !strcmp(reg->problems[i].plugin, name))
            refused = &reg->problems[i];
    for (uint32_t i = 0; i < reg->n_problems && !refused; i++) {
        const char *base = strrchr(reg->problems[i].pub.file, '/');
        base = base ? base + 1 : reg->problems[i].pub.file;
        size_t n = strlen(name);
        if (!strncmp(base, name, n) && !strcmp(base + n, ".so")) refused = &reg->problems[i];
    }
    if (refused) {
        err_set(err, "plugin '%s' was found but cannot be used: %s", name, refused->pub.message);
        return NULL;
    }

    err_set(err, "no %s%splugin called '%s'", kname, kind ? " " : "", name);
    const char *nearest = NULL;
    size_t best = edit_distance_near_limit(name) + 1;
    for (uint32_t i = 0; i < reg->n_plugins; i++) {
        const sylva_plugin *d = reg->plugins[i]->desc;
        if (kind && d->kind != kind) continue;
        size_t dist = edit_distance(name, d->name);
        if (dist < best) best = dist, nearest = d->name;
    }
    if (nearest) err_append(err, " (did you mean '%s'?)", nearest);
    err_append_inventory(err, reg, kind);
    return NULL;
}
