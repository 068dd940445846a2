/* plugin_manifest.c — reading and writing the manifest beside a plugin module
 * (plugin_manifest.h). Reading never opens the module; writing is the one place that must. */
#include <dlfcn.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "io/atomic_file.h"
#include "plugin/plugin_manifest.h"
#include "plugin/plugin_names.h"

#define MANIFEST_HEADER "sylva-plugin-manifest 1"

int plugin_manifest_path(const char *module, char *buf, size_t cap)
{
    size_t n = module ? strlen(module) : 0;
    if (n < 4 || strcmp(module + n - 3, ".so")) return -1;
    int w = snprintf(buf, cap, "%.*s%s", (int)(n - 3), module, PLUGIN_MANIFEST_SUFFIX);
    return w < 0 || (size_t)w >= cap ? -1 : 0;
}

static sylva_kind kind_from_name(const char *s, int *ok)
{
    *ok = 1;
    for (int k = SYLVA_KIND_TERRAIN; k <= SYLVA_KIND_ECOLOGY; k++)
        if (!strcmp(s, plugin_kind_name((sylva_kind)k))) return (sylva_kind)k;
    *ok = !strcmp(s, "unknown");
    return (sylva_kind)0;
}

/* Parses one "plugin NAME KIND MAJOR.MINOR" line (after the keyword) into *p; 0 or -1 with why. */
static int parse_plugin_line(const char *rest, manifest_plugin *p, char *why, size_t cap)
{
    char name[80], kind[32];
    unsigned major, minor;
    int used = 0;
    if (sscanf(rest, " %79s %31s %u.%u %n", name, kind, &major, &minor, &used) != 4 ||
        rest[used] != '\0') {
        snprintf(why, cap, "expected `plugin NAME KIND MAJOR.MINOR`");
        return -1;
    }
    if (!plugin_name_is_valid(name)) {
        snprintf(why, cap, "'%.*s' is not a plugin name: a lowercase letter, then lowercase "
                 "letters, digits or '_', at most %d bytes", PLUGIN_NAME_MAX + 1, name,
                 PLUGIN_NAME_MAX);
        return -1;
    }
    int ok;
    p->kind = kind_from_name(kind, &ok);
    if (!ok) {
        snprintf(why, cap, "unknown kind '%s'; kinds are terrain, tree and ecology", kind);
        return -1;
    }
    snprintf(p->name, sizeof p->name, "%s", name);
    p->abi_major = major, p->abi_minor = minor;
    return 0;
}

int plugin_manifest_read(const char *path, plugin_manifest *m, err_buf *err)
{
    memset(m, 0, sizeof *m);
    struct stat st;
    if (stat(path, &st) != 0) {
        if (errno == ENOENT) return 0;
        return err_set(err, "%s: cannot read the plugin manifest: %s", path, strerror(errno));
    }
    if (!S_ISREG(st.st_mode))
        return err_set(err, "%s: the plugin manifest is not a regular file", path);
    if (st.st_size > PLUGIN_MANIFEST_MAX_BYTES)
        return err_set(err, "%s: the plugin manifest is %lld bytes; a manifest is at most %d",
                       path, (long long)st.st_size, PLUGIN_MANIFEST_MAX_BYTES);
    FILE *f = fopen(path, "r"); /* closed below */
    if (!f) return err_set(err, "%s: cannot read the plugin manifest: %s", path, strerror(errno));
    char line[256], why[200];
    int rc = 0, header = 0;
    unsigned no = 0;
    while (rc == 0 && fgets(line, sizeof line, f)) {
        no++;
        size_t len = strlen(line);
        if (len && line[len - 1] == '\n') line[--len] = '\0';
        else if (!feof(f)) {
            rc = err_set(err, "%s:%u: the line is longer than %zu bytes", path, no,
                         sizeof line - 2);
            break;
        }
        const char *s = line;
        while (*s == ' ' || *s == '\t') s++;
        if (!*s || *s == '#') continue;
        if (!header) {
            if (strcmp(s, MANIFEST_HEADER))
                rc = err_set(err, "%s:%u: a plugin manifest starts with `%s`", path, no,
                             MANIFEST_HEADER);
            header = 1;
        } else if (!strncmp(s, "plugin ", 7)) {
            if (m->n == PLUGIN_MANIFEST_MAX_PLUGINS)
                rc = err_set(err, "%s:%u: more than %d plugins; a module holds at most %d", path,
                             no, PLUGIN_MANIFEST_MAX_PLUGINS, PLUGIN_MANIFEST_MAX_PLUGINS);
            else if (parse_plugin_line(s + 7, &m->plugin[m->n], why, sizeof why))
                rc = err_set(err, "%s:%u: %s", path, no, why);
            else
                m->n++;
        } else {
            rc = err_set(err, "%s:%u: unknown line; a manifest holds `plugin NAME KIND "
                         "MAJOR.MINOR` lines", path, no);
        }
    }
    if (rc == 0 && ferror(f)) rc = err_set(err, "%s: cannot read the plugin manifest", path);
    fclose(f);
    if (rc == 0 && m->n == 0)
        rc = err_set(err, "%s: the plugin manifest names no plugin", path);
    return rc ? -1 : 1;
}

int plugin_manifest_declares(const plugin_manifest *m, const char *name)
{
    for (uint32_t i = 0; m && i < m->n; i++)
        if (!strcmp(m->plugin[i].name, name)) return 1;
    return 0;
}

/* Reads the descriptors of the open module into *m; 0 or -1 with err. */
static int manifest_from_module(void *handle, const char *module, plugin_manifest *m,
                                err_buf *err)
{
    memset(m, 0, sizeof *m);
    void *entry = dlsym(handle, SYLVA_PLUGIN_ENTRY);
    if (!entry)
        return err_set(err, "no entry point [%s] in shared library [%s]", SYLVA_PLUGIN_ENTRY,
                       module);
    sylva_plugin_get_fn get = (sylva_plugin_get_fn)entry;
    const sylva_plugin *d;
    for (uint32_t i = 0; (d = get(i)) != NULL; i++) {
        if (i == PLUGIN_MANIFEST_MAX_PLUGINS)
            return err_set(err, "%s: %s: more than %d descriptors", module, SYLVA_PLUGIN_ENTRY,
                           PLUGIN_MANIFEST_MAX_PLUGINS);
        if (d->size < SYLVA_FIELD_END(sylva_plugin, name) || !plugin_name_is_valid(d->name))
            return err_set(err, "%s: %s(%u): the descriptor has no valid name", module,
                           SYLVA_PLUGIN_ENTRY, i);
        manifest_plugin *p = &m->plugin[m->n++];
        snprintf(p->name, sizeof p->name, "%s", d->name);
        p->kind = d->kind >= SYLVA_KIND_TERRAIN && d->kind <= SYLVA_KIND_ECOLOGY ? d->kind : 0;
        p->abi_major = d->abi_major, p->abi_minor = d->abi_minor;
    }
    if (m->n == 0)
        return err_set(err, "%s: %s(0) returned NULL: the module provides no plugin", module,
                       SYLVA_PLUGIN_ENTRY);
    return 0;
}

int plugin_manifest_write(const char *module, err_buf *err)
{
    char path[4096];
    if (plugin_manifest_path(module, path, sizeof path))
        return err_set(err, "%s: a plugin module's file name ends in .so", module);
    dlerror();
    void *handle = dlopen(module, RTLD_NOW | RTLD_LOCAL); /* closed below */
    if (!handle) {
        const char *why = dlerror();
        return err_set(err, "%s: cannot load shared library: %s", module, why ? why : "unknown");
    }
    plugin_manifest *m = malloc(sizeof *m); /* owned here */
    int rc = m ? manifest_from_module(handle, module, m, err)
               : err_nomem(err, "out of memory while reading %s", module);
    dlclose(handle);
    atomic_file af;
    FILE *f = rc == 0 ? atomic_file_open_stream(&af, path, err) : NULL; /* af owns it */
    if (rc == 0 && !f) rc = -1;
    if (f) {
        const char *base = strrchr(module, '/');
        fprintf(f, "# %s: the plugins of %s, read before the module is opened.\n"
                "# Written by `sylva plugins --manifest`; see docs/plugins.md.\n%s\n",
                strrchr(path, '/') ? strrchr(path, '/') + 1 : path, base ? base + 1 : module,
                MANIFEST_HEADER);
        for (uint32_t i = 0; i < m->n; i++)
            fprintf(f, "plugin %s %s %u.%u\n", m->plugin[i].name,
                    plugin_kind_name(m->plugin[i].kind), m->plugin[i].abi_major,
                    m->plugin[i].abi_minor);
        rc = atomic_file_commit(&af, err);
    }
    free(m);
    return rc ? -1 : 0;
}
