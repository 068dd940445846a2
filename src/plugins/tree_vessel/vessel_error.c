/* vessel_error.c — fills a vessel_err. */
#include "vessel_error.h"

#include <stdarg.h>
#include <stdio.h>

int vessel_fail(vessel_err *err, vessel_fault fault, const char *param, const char *fmt, ...)
{
    if (!err) return fault;
    err->fault = fault;
    snprintf(err->param, sizeof err->param, "%s", param ? param : "");
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->msg, sizeof err->msg, fmt, ap);
    va_end(ap);
    return fault;
}
