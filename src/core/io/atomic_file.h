/* atomic_file.h — write-then-rename: a temporary name beside the target, renamed into place
 * only when the whole file has been written. */
#ifndef SYLVA_ATOMIC_FILE_H
#define SYLVA_ATOMIC_FILE_H

#include <stddef.h>

#include "util/err.h"

/* Fills tmp (size n) with a temporary path in path's folder: "<path>.tmp-<pid>-<counter>".
 * Returns 0 or -1 when it does not fit. */
int atomic_temp_name(const char *path, char *tmp, size_t n, err_buf *err);
/* Renames tmp to path; on failure removes tmp and sets err. */
int atomic_commit(const char *tmp, const char *path, err_buf *err);

#endif
