/* atomic_file.c — temporary names and the final rename. */
#include "io/atomic_file.h"

#include <errno.h>
#include <stdatomic.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

int atomic_temp_name(const char *path, char *tmp, size_t n, err_buf *err)
{
    static atomic_uint counter;
    unsigned c = atomic_fetch_add(&counter, 1);
    int k = snprintf(tmp, n, "%s.tmp-%ld-%u", path, (long)getpid(), c);
    if (k < 0 || (size_t)k >= n) return err_set(err, "%s: output path is too long", path);
    return 0;
}

int atomic_commit(const char *tmp, const char *path, err_buf *err)
{
    if (rename(tmp, path) != 0) {
        int e = errno;
        remove(tmp);
        return err_set(err, "%s: cannot move the finished file into place: %s", path, strerror(e));
    }
    return 0;
}
