/* err.c — filling err_buf sentences. */
#include "util/err.h"

#include <stdio.h>
#include <string.h>

int err_vset(err_buf *e, const char *fmt, va_list ap)
{
    if (e) vsnprintf(e->msg, sizeof e->msg, fmt, ap);
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
    return -1;
}

void err_clear(err_buf *e)
{
    if (e) e->msg[0] = '\0';
}
