/* plugin_err.c — filling the failure report of a plugin's model. */
#include "plugin_err.h"

#include <stdarg.h>
#include <stdio.h>

static int vfail(plugin_err *e, int status, const sylva_params *where, const char *param, const char *fmt,
                 va_list ap)
{
    if (e) {
        e->status = status, e->where = where;
        snprintf(e->param, sizeof e->param, "%s", param ? param : "");
        vsnprintf(e->msg, sizeof e->msg, fmt, ap);
    }
    return status;
}

int plugin_fail(plugin_err *e, int status, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfail(e, status, NULL, NULL, fmt, ap);
    va_end(ap);
    return status;
}

int plugin_fail_param(plugin_err *e, const sylva_params *where, const char *param, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfail(e, SYLVA_ERR_PARAM, where, param, fmt, ap);
    va_end(ap);
    return SYLVA_ERR_PARAM;
}

int plugin_fail_key(plugin_err *e, int status, const sylva_params *where, const char *param, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfail(e, status, where, param, fmt, ap);
    va_end(ap);
    return status;
}
