/* err.c — filling err_buf: its sentence, kind and place. */
#include "util/err.h"

#include <stdio.h>
#include <string.h>

/* Writes the sentence and the place (file NULL: none); the kind is the caller's to set. */
static void err_write(err_buf *e, const char *file, uint32_t line, uint32_t column, const char *fmt, va_list ap)
{
    size_t at = 0;
    e->file[0] = '\0', e->line = e->column = 0;
    if (file) {
        snprintf(e->file, sizeof e->file, "%s", file);
        e->line = line, e->column = column;
        int n = line ? snprintf(e->msg, sizeof e->msg, "%s:%u:%u: ", file, line, column)
                     : snprintf(e->msg, sizeof e->msg, "%s: ", file);
        at = n < 0 ? 0 : (size_t)n < sizeof e->msg ? (size_t)n : sizeof e->msg - 1;
    }
    vsnprintf(e->msg + at, sizeof e->msg - at, fmt, ap);
    e->text_at = (uint32_t)at;
}

int err_vset(err_buf *e, const char *fmt, va_list ap)
{
    if (!e) return -1;
    err_write(e, NULL, 0, 0, fmt, ap);
    e->status = ERR_UNSTATED;
    return -1;
}

int err_set(err_buf *e, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    err_vset(e, fmt, ap);
    va_end(ap);
    return -1;
}

int err_fail(err_buf *e, err_status status, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    err_vset(e, fmt, ap);
    va_end(ap);
    if (e) e->status = status;
    return -1;
}

int err_vat(err_buf *e, err_status status, const char *file, uint32_t line, uint32_t column, const char *fmt,
            va_list ap)
{
    if (!e) return -1;
    err_write(e, file && *file ? file : NULL, line, column, fmt, ap);
    e->status = status;
    return -1;
}

int err_at(err_buf *e, err_status status, const char *file, uint32_t line, uint32_t column, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    err_vat(e, status, file, line, column, fmt, ap);
    va_end(ap);
    return -1;
}

int err_locate(err_buf *e, const char *file, uint32_t line, uint32_t column)
{
    if (!e || e->file[0]) return -1;
    char text[ERR_MSG_MAX];
    memcpy(text, e->msg, sizeof text);
    return err_at(e, e->status, file, line, column, "%s", text);
}

int err_prefix(err_buf *e, const char *fmt, ...)
{
    if (!e) return -1;
    char head[ERR_MSG_MAX], old[ERR_MSG_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(head, sizeof head, fmt, ap);
    va_end(ap);
    memcpy(old, e->msg, sizeof old);
    snprintf(e->msg, sizeof e->msg, "%s%s", head, old);
    e->text_at = 0; /* the sentence no longer starts with its place */
    return -1;
}

int err_default(err_buf *e, err_status status)
{
    if (e && e->status == ERR_UNSTATED) e->status = status;
    return -1;
}

const char *err_sentence(const err_buf *e) { return e->msg + e->text_at; }

int err_has_place(const err_buf *e) { return e->file[0] != '\0'; }

void err_clear(err_buf *e)
{
    if (!e) return;
    e->msg[0] = e->file[0] = '\0';
    e->status = ERR_UNSTATED;
    e->line = e->column = e->text_at = 0;
}
