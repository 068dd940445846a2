/* lsys_error.c — filling the model's error sentence. */
#include "lsys_error.h"

#include <stdio.h>

int lsys_fail(lsys_error *e, int status, const char *fmt, ...)
{
    if (e) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(e->msg, sizeof e->msg, fmt, ap);
        va_end(ap);
    }
    return status;
}
