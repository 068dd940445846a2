/* output_guard.c — the inputs of the run by device and inode, and the refusal of an output
 * that is one of them. */
#include "io/output_guard.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

typedef struct guarded_input {
    dev_t dev;
    ino_t ino;
    char *path; /* as given; malloc'ed */
    char *what; /* malloc'ed */
} guarded_input;

static guarded_input *inputs; /* malloc'ed; n_inputs used of cap */
static size_t n_inputs, cap;

int output_guard_add(const char *path, const char *what, err_buf *err)
{
    struct stat st;
    if (!path || stat(path, &st)) return 0;
    for (size_t i = 0; i < n_inputs; i++)
        if (inputs[i].dev == st.st_dev && inputs[i].ino == st.st_ino) return 0;
    if (n_inputs == cap) {
        size_t c = cap ? 2 * cap : 16;
        guarded_input *g = realloc(inputs, c * sizeof *g);
        if (!g) return err_nomem(err, "out of memory listing the run's input files");
        inputs = g, cap = c;
    }
    guarded_input g = {st.st_dev, st.st_ino, strdup(path), strdup(what)};
    if (!g.path || !g.what) {
        free(g.path), free(g.what);
        return err_nomem(err, "out of memory listing the run's input files");
    }
    inputs[n_inputs++] = g;
    return 0;
}

int output_guard_check(const char *path, err_buf *err)
{
    struct stat st;
    if (!path || !n_inputs || stat(path, &st)) return 0;
    for (size_t i = 0; i < n_inputs; i++)
        if (inputs[i].dev == st.st_dev && inputs[i].ino == st.st_ino)
            return err_fail(err, ERR_USAGE, "the output '%s' is %s '%s'; writing it would replace that input, so "
                            "name another output", path, inputs[i].what, inputs[i].path);
    return 0;
}

/* path with its folder resolved (realpath) into out; the path as given when the folder does
 * not exist. */
static void resolved_name(const char *path, char *out, size_t n)
{
    const char *slash = strrchr(path, '/');
    char dir[PATH_MAX + 1], real[PATH_MAX + 1];
    if (!slash) snprintf(dir, sizeof dir, ".");
    else if (slash == path) snprintf(dir, sizeof dir, "/");
    else snprintf(dir, sizeof dir, "%.*s", (int)(slash - path), path);
    if (realpath(dir, real)) snprintf(out, n, "%s/%s", real, slash ? slash + 1 : path);
    else snprintf(out, n, "%s", path);
}

int output_guard_same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    int ea = !stat(a, &sa), eb = !stat(b, &sb);
    if (ea && eb) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    if (ea != eb) return 0;
    char ra[2 * PATH_MAX + 2], rb[2 * PATH_MAX + 2];
    resolved_name(a, ra, sizeof ra);
    resolved_name(b, rb, sizeof rb);
    return !strcmp(ra, rb);
}

void output_guard_clear(void)
{
    for (size_t i = 0; i < n_inputs; i++) free(inputs[i].path), free(inputs[i].what);
    free(inputs);
    inputs = NULL, n_inputs = cap = 0;
}
