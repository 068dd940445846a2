/* err.h — the core's error: a sentence, what kind of failure it is, and where in which file the
 * problem lies. A failing function fills an err_buf and returns -1; the command line turns the
 * kind into the exit status (cli/cli_status.h) and prints the sentence. No allocation, so
 * reporting works when memory is short.
 *
 * The sentence reads "file:line:column: what is wrong, what would be valid" when the place is
 * known (err_at, err_locate); the place is then also in file/line/column, so no caller has to
 * read it back out of the text. */
#ifndef SYLVA_ERR_H
#define SYLVA_ERR_H

#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#define ERR_MSG_MAX 2048
#define ERR_FILE_MAX 1024

/* What kind of failure: the command line's exit status follows from it alone. */
typedef enum err_status {
    ERR_UNSTATED = 0, /* err_set: the kind is left to the caller that knows it (err_default) */
    ERR_USAGE,        /* a bad command line */
    ERR_INPUT,        /* a bad scene file or file it names, a missing plugin */
    ERR_LIMIT,        /* the input asks for more than a documented limit allows */
    ERR_PLUGIN,       /* a plugin reported a failure */
    ERR_OUTPUT,       /* an output file could not be written */
    ERR_NOMEM,        /* an allocation failed, in the core or in a plugin */
    ERR_INTERNAL      /* anything else: a library failed, a bug */
} err_status;

typedef struct err_buf {
    char msg[ERR_MSG_MAX];   /* "" when no error has been set; the whole sentence as printed */
    err_status status;
    char file[ERR_FILE_MAX]; /* where the problem lies; "" when no place is known */
    uint32_t line, column;   /* 1-based; 0 when only the file is known */
    uint32_t text_at;        /* msg + text_at is the sentence after its "file:line:column: " */
} err_buf;

/* Sets the sentence (printf-style), with no status and no place, and returns -1, for
 * `return err_set(e, ...)`. e may be NULL (as for every function here). */
int err_set(err_buf *e, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
int err_vset(err_buf *e, const char *fmt, va_list ap);
/* The same with a status. */
int err_fail(err_buf *e, err_status status, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
/* The same with ERR_NOMEM: "out of memory ..." sentences. */
#define err_nomem(e, ...) err_fail((e), ERR_NOMEM, __VA_ARGS__)
/* The same with a status and a place: the sentence becomes "file:line:column: ...". */
int err_at(err_buf *e, err_status status, const char *file, uint32_t line, uint32_t column, const char *fmt, ...)
    __attribute__((format(printf, 6, 7)));
int err_vat(err_buf *e, err_status status, const char *file, uint32_t line, uint32_t column, const char *fmt,
            va_list ap);

/* Places a sentence that has no place yet at file:line:column (prefixing it); one that has a
 * place keeps it, being the more precise. Returns -1. */
int err_locate(err_buf *e, const char *file, uint32_t line, uint32_t column);
/* Adds context before the whole sentence ("while loading x: ..."); status and place stay (a
 * caller adding its own place uses err_locate after it). Returns -1. */
int err_prefix(err_buf *e, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Gives a sentence whose kind is unstated the kind the caller knows; a stated kind (out of
 * memory in a writer, say) stays. Returns -1. */
int err_default(err_buf *e, err_status status);

/* The sentence without its place. */
const char *err_sentence(const err_buf *e);
/* 1 when a place is known. */
int err_has_place(const err_buf *e);
void err_clear(err_buf *e);

#endif
