/* output_guard.h — the files a run reads, which none of its outputs may replace.
 *
 * A command lists its inputs (the scene file, the files it includes and names, a state file to
 * load) before it writes anything; every output then goes through atomic_file_open, which asks
 * output_guard_check and refuses a target that is one of them. Files are told apart by what
 * they are (device and inode, after symbolic links), not by how they are spelled, so
 * "./a.yaml", "a.yaml" and a link to it are one file.
 *
 * Ownership: the list is the process's; output_guard_clear releases it. It is filled before
 * any thread writes and only read while they do. */
#ifndef SYLVA_OUTPUT_GUARD_H
#define SYLVA_OUTPUT_GUARD_H

#include "util/err.h"

/* Adds path, named in refusals as `what` ("the scene file"), to the inputs no output may
 * replace; a path that names no existing file is left out (nothing there to lose). Returns 0,
 * or -1 with err (ERR_NOMEM). */
int output_guard_add(const char *path, const char *what, err_buf *err);
/* 0 when writing to path replaces none of the inputs; otherwise -1 with err (ERR_USAGE) naming
 * the output and the input it is. */
int output_guard_check(const char *path, err_buf *err);
/* 1 when a and b name the same file: the same device and inode when both exist, else the same
 * name once their folders are resolved (two outputs not written yet). */
int output_guard_same_file(const char *a, const char *b);
void output_guard_clear(void);

#endif
