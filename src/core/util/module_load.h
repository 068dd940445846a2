/* module_load.h — the core's own modules: shared libraries that carry a large third-party library
 * (OpenImageIO for images, Assimp for models), opened with dlopen the first time a command needs
 * them, so that a command that never does (a ZTV) never loads them. A module is looked for as an
 * environment variable names it (a file), else in the build tree's lib/ (a program run from the
 * build tree), then in the install folder; once opened it stays open until the process ends.
 */
#ifndef SYLVA_MODULE_LOAD_H
#define SYLVA_MODULE_LOAD_H

#include <stddef.h>

/* The address of the function `entry` in the module `file` (found as above: env's value when it
 * is set and not empty, else SYLVA_BUILD_ROOT/lib/file for a program of the build tree, else
 * install_dir/file), with *so its handle for dlclose; or NULL with why set (dlerror's words, or
 * the missing entry). */
void *module_load(const char *env, const char *file, const char *install_dir, const char *entry, void **so,
                  char *why, size_t n);

#endif
