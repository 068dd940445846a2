/* module_load.c — a module of the core found and opened (util/module_load.h). */
#include "util/module_load.h"

#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>

#include "util/build_tree.h"

/* The entry of the module at path, *so set; or NULL with why. */
static void *open_at(const char *path, const char *entry, void **so, char *why, size_t n)
{
    void *handle = dlopen(path, RTLD_NOW | RTLD_LOCAL); /* the caller's: kept, or dlclose'd */
    if (!handle) {
        snprintf(why, n, "%s", dlerror());
        return NULL;
    }
    void *fn = dlsym(handle, entry);
    if (!fn) {
        snprintf(why, n, "%s: no entry point %s in the shared library", path, entry);
        dlclose(handle);
        return NULL;
    }
    *so = handle;
    return fn;
}

void *module_load(const char *env, const char *file, const char *install_dir, const char *entry, void **so,
                  char *why, size_t n)
{
    char path[4096];
    const char *named = getenv(env);
    if (named && *named) return open_at(named, entry, so, why, n);
    void *fn = NULL;
    if (build_tree_running() && snprintf(path, sizeof path, "%s/lib/%s", SYLVA_BUILD_ROOT, file) < (int)sizeof path)
        fn = open_at(path, entry, so, why, n);
    if (!fn && snprintf(path, sizeof path, "%s/%s", install_dir, file) < (int)sizeof path)
        fn = open_at(path, entry, so, why, n);
    return fn;
}
