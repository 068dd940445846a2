/* ifs_err.c — filling the model's failure sentence. */
#include "ifs_err.h"

#include <stdarg.h>
#include <stdio.h>

int ifs_fail(ifs_err *e, int status, const char *fmt, ...)
{
    if (e) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(e->msg, sizeof e->msg, fmt, ap);
        va_end(ap);
    }
    return status;
}
