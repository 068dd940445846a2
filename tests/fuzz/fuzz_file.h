/* fuzz_file.h — what the fuzz targets that read a file share: the input written to a file of
 * the process's own scratch folder (work_dir.h owns the folder and removes it at exit), and a
 * failure that ends the run as a finding. Header-only, for the fuzz targets. */
#ifndef SYLVA_FUZZ_FILE_H
#define SYLVA_FUZZ_FILE_H

#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "work_dir.h"

/* A finding that no sanitizer sees (a failure without a sentence, a result out of its range):
 * said on stderr, then abort() so that libFuzzer keeps the input. */
static inline void fuzz_finding(const char *target, const char *what)
{
    fprintf(stderr, "%s: %s\n", target, what);
    abort();
}

/* The path of NAME in the scratch folder, copied into buf (static storage of the caller). */
static inline const char *fuzz_scratch_path(const char *name, char *buf, size_t cap)
{
    snprintf(buf, cap, "%s", work_path(name));
    return buf;
}

/* Replaces the contents of the file at path with data (a failure to write is a finding). The
 * file is overwritten and then cut to size, not truncated first: ext4 flushes a file truncated
 * to zero and rewritten when it is closed, which would make disk writes the cost of every
 * execution. */
static inline void fuzz_write_file(const char *target, const char *path, const uint8_t *data, size_t size)
{
    int fd = open(path, O_WRONLY | O_CREAT, 0600);
    size_t done = 0;
    while (fd >= 0 && done < size) {
        ssize_t w = pwrite(fd, data + done, size - done, (off_t)done);
        if (w <= 0) break;
        done += (size_t)w;
    }
    int bad = fd < 0 || done != size || ftruncate(fd, (off_t)size) != 0;
    if (fd >= 0) bad |= close(fd) != 0;
    if (bad) {
        fprintf(stderr, "%s: cannot write %s\n", target, path);
        abort();
    }
}

#endif
