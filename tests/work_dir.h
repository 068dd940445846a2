/* work_dir.h — a test process's own scratch folder: made on first use as
 * $TMPDIR/sylva-test-<pid>-<k> (TMPDIR unset: /tmp), the first k that does not exist yet, and
 * removed with everything in it when the process exits. Header-only, for the test executables. */
#ifndef SYLVA_TEST_WORK_DIR_H
#define SYLVA_TEST_WORK_DIR_H

#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

static char work_dir_path[1024];

/* Removes path and, when it is a folder (not a link to one), everything in it. */
static void work_dir_remove_tree(const char *path)
{
    struct stat st;
    if (lstat(path, &st) != 0) return;
    if (S_ISDIR(st.st_mode)) {
        DIR *d = opendir(path);
        if (d) {
            char child[1200];
            for (struct dirent *e; (e = readdir(d));) {
                if (e->d_name[0] == '.' && (!e->d_name[1] || (e->d_name[1] == '.' && !e->d_name[2]))) continue;
                snprintf(child, sizeof child, "%s/%s", path, e->d_name);
                work_dir_remove_tree(child);
            }
            closedir(d);
        }
        rmdir(path);
    } else {
        unlink(path);
    }
}

static void work_dir_remove(void) { work_dir_remove_tree(work_dir_path); }

/* The folder's path; exits the test with status 2 when it cannot be made. */
static inline const char *work_dir(void)
{
    if (work_dir_path[0]) return work_dir_path;
    const char *base = getenv("TMPDIR");
    if (!base || !*base) base = "/tmp";
    for (unsigned k = 0; k < 1000; k++) {
        snprintf(work_dir_path, sizeof work_dir_path, "%s/sylva-test-%ld-%u", base, (long)getpid(), k);
        if (mkdir(work_dir_path, 0700) == 0) {
            atexit(work_dir_remove);
            return work_dir_path;
        }
        if (errno != EEXIST) break;
    }
    fprintf(stderr, "cannot make a work folder in %s\n", base);
    exit(2);
}

/* Entries of folder dir, "." and ".." aside; -1 when it cannot be read. */
static inline int work_dir_entries(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d) return -1;
    int n = 0;
    for (struct dirent *e; (e = readdir(d));)
        if (!(e->d_name[0] == '.' && (!e->d_name[1] || (e->d_name[1] == '.' && !e->d_name[2])))) n++;
    closedir(d);
    return n;
}

/* NAME inside the work folder. The string lives until the next call. */
static inline const char *work_path(const char *name)
{
    static char path[1200];
    snprintf(path, sizeof path, "%s/%s", work_dir(), name);
    return path;
}

/* Writes text to NAME inside the work folder; returns its path (as work_path) or NULL. */
static inline const char *work_file(const char *name, const char *text)
{
    const char *path = work_path(name);
    FILE *f = fopen(path, "w");
    if (!f) return NULL;
    int bad = fputs(text, f) < 0;
    bad |= fclose(f) != 0;
    return bad ? NULL : path;
}

#endif
