/* plugin_err.c — filling the failure report of a plugin's model. */
#include "plugin_err.h"

#include <stdarg.h>
#include <stdio.h>

int plugin_fail(plugin_err *e, int status, const char *fmt, ...)
{
    if (e) {
        e->status = status, e->where = NULL, e->param[0] = '\0';
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(e->msg, sizeof e->msg, fmt, ap);
        va_end(ap);
    }
    return status;
}

int plugin_fail_param(plugin_err *e, const sylva_params *where, const char *param, const char *fmt, ...)
{
    if (e) {
        e->status = SYLVA_ERR_PARAM, e->where = where;
        snprintf(e->param, sizeof e->param, "%s", param);
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(e->msg, sizeof e->msg, fmt, ap);
        va_end(ap);
    }
    return SYLVA_ERR_PARAM;
}
