/* build_tree.c — is the executable inside SYLVA_BUILD_ROOT (build_tree.h)? */
#include "util/build_tree.h"

#include <stdlib.h>
#include <string.h>

int build_tree_running(void)
{
    char *exe = realpath("/proc/self/exe", NULL); /* malloc'ed by libc, freed below */
    char *root = realpath(SYLVA_BUILD_ROOT, NULL); /* likewise */
    size_t n = root ? strlen(root) : 0;
    int inside = exe && root && !strncmp(exe, root, n) && exe[n] == '/';
    free(exe);
    free(root);
    return inside;
}
