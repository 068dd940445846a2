/* cli_status.h — how a `sylva` command ends: its exit status, decided in one place from the
 * kind of failure (err_status, util/err.h), and the failure's sentence on stderr.
 *
 * Exit statuses (README.md, `sylva --help`): 0 done, 1 usage, 2 bad scene or plugin failure,
 * 3 output not written, 4 out of memory or internal error. */
#ifndef SYLVA_CLI_STATUS_H
#define SYLVA_CLI_STATUS_H

#include "util/err.h"

enum {
    EXIT_OK = 0,
    EXIT_USAGE = 1 /* a bad command line, found by the command itself */
};

/* The exit status for a kind of failure; ERR_UNSTATED counts as internal. */
int cli_exit_status(err_status status);

/* Ends a command that failed: gives err's sentence the kind `otherwise` when it states none,
 * prints it on stderr — as it is when it is placed in a file or cmd is NULL, else after
 * "sylva CMD: " — and returns the exit status for its kind. */
int cli_fail(const char *cmd, err_buf *err, err_status otherwise);

/* The same for a sentence the command writes itself (printf-style) with its kind. */
int cli_failf(const char *cmd, err_status status, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

#endif
