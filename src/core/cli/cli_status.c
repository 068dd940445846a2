/* cli_status.c — the one place where a kind of failure becomes an exit status. */
#include "cli/cli_status.h"

#include <stdio.h>

int cli_exit_status(err_status status)
{
    switch (status) {
    case ERR_USAGE:
        return EXIT_USAGE;
    case ERR_INPUT:
    case ERR_LIMIT:
    case ERR_PLUGIN:
        return 2;
    case ERR_OUTPUT:
        return 3;
    case ERR_NOMEM:
    case ERR_INTERNAL:
    case ERR_UNSTATED:
        break;
    }
    return 4;
}

int cli_fail(const char *cmd, err_buf *err, err_status otherwise)
{
    err_default(err, otherwise);
    if (!cmd || err_has_place(err)) fprintf(stderr, "%s\n", err->msg);
    else fprintf(stderr, "sylva %s: %s\n", cmd, err->msg);
    return cli_exit_status(err->status);
}

int cli_failf(const char *cmd, err_status status, const char *fmt, ...)
{
    err_buf err;
    va_list ap;
    va_start(ap, fmt);
    err_vset(&err, fmt, ap);
    va_end(ap);
    err.status = status;
    return cli_fail(cmd, &err, status);
}
