/* err.h — the core's error sentence: a fixed buffer that a failing function fills and returns
 * a negative status for. No allocation, so reporting works when memory is short. */
#ifndef SYLVA_ERR_H
#define SYLVA_ERR_H

#include <stdarg.h>
#include <stddef.h>

#define ERR_MSG_MAX 2048

typedef struct err_buf {
    char msg[ERR_MSG_MAX]; /* "" when no error has been set */
} err_buf;

/* Sets the message (printf-style) and returns -1, for `return err_set(e, ...)`. e may be NULL. */
int err_set(err_buf *e, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
int err_vset(err_buf *e, const char *fmt, va_list ap);
/* Prefixes the existing message with printf-style context ("while loading x: ..."). */
int err_prefix(err_buf *e, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void err_clear(err_buf *e);

#endif
