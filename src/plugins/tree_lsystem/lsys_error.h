/* lsys_error.h — the error sentence of the L-system model: a fixed buffer that a failing
 * function fills before it returns a negative status. No allocation, so a report still works
 * when memory has run out. The plugin entry copies the sentence into api->error(). */
#ifndef LSYS_ERROR_H
#define LSYS_ERROR_H

#include <stdarg.h>

#define LSYS_ERROR_MAX 1024

/* Status codes of the model; the plugin maps them onto sylva_status. */
enum {
    LSYS_OK = 0,
    LSYS_ERR_SYNTAX = -1, /* the L-system text is wrong (file:line:column in the sentence) */
    LSYS_ERR_LIMIT = -2,  /* a documented limit was reached (the sentence names it) */
    LSYS_ERR_NOMEM = -3,  /* an allocation failed */
    LSYS_ERR_IO = -4,     /* a file could not be read */
    LSYS_ERR_SINK = -5    /* the geometry consumer refused (its own sentence is kept) */
};

typedef struct lsys_error {
    char msg[LSYS_ERROR_MAX]; /* "" while no error was set */
} lsys_error;

/* Sets the sentence (printf-style) and returns `status`, for `return lsys_fail(e, ...)`.
 * e may be NULL. */
int lsys_fail(lsys_error *e, int status, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

#endif
