/* pov_file.h — one POV-Ray scene file being streamed: opened under a temporary name with a large
 * stdio buffer, renamed into place by pov_file_finish only when everything was written, removed
 * by pov_file_abort otherwise. Also the small text builders the writers share: numbers and
 * vectors appended to a line buffer.
 *
 * Ownership: a pov_file owns its FILE and buffer until finish or abort (both accept a file that
 * was never opened). */
#ifndef SYLVA_POV_FILE_H
#define SYLVA_POV_FILE_H

#include <stdint.h>
#include <stdio.h>

#include "io/atomic_file.h"
#include "util/err.h"

#define POV_PATH_MAX 4096

typedef struct pov_file {
    FILE *f;                      /* the temporary's stream (owned by out) */
    char *buffer;                 /* stdio buffer; owned */
    atomic_file out;              /* the temporary beside the target */
} pov_file;

int pov_file_open(pov_file *pf, const char *path, err_buf *err);
/* Flushes, checks for write errors and renames into place; adds the size to *bytes when bytes
 * is not NULL. Returns 0 or -1 with err set (the temporary is removed). */
int pov_file_finish(pov_file *pf, uint64_t *bytes, err_buf *err);
void pov_file_abort(pov_file *pf);

void pov_put(pov_file *pf, const char *text);
void pov_printf(pov_file *pf, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Appenders: each writes at p and returns the new end (NUL-terminated). A non-finite value is
 * written as 0 and counted in *bad when bad is not NULL. */
char *pov_append_text(char *p, const char *text);
char *pov_append_uint(char *p, uint64_t v);
char *pov_append_real(char *p, double v, int digits, int *bad);
char *pov_append_float(char *p, float v, int *bad);
/* As pov_append_float, for a position POV-Ray keeps in double precision (pov_format_position). */
char *pov_append_position(char *p, float v, int *bad);
/* "<a, b, c>" with `digits` significant digits. */
char *pov_append_vec3(char *p, const double v[3], int digits, int *bad);
/* "<a, b, c>", each the shortest text that reads back as the same float. */
char *pov_append_vec3f(char *p, float x, float y, float z, int *bad);

#endif
