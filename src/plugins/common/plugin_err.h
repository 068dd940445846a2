/* plugin_err.h — how a plugin's model reports a failure without calling the host: a
 * sylva_status, one sentence (what is wrong, what would be valid) and, when a scene-file key is
 * at fault, the block and the key. The plugin file hands it on with plugin_report()
 * (plugin_host.h): api->param_error at the key's place, else api->error. No allocation, so
 * reporting works when memory is short. */
#ifndef PLUGIN_ERR_H
#define PLUGIN_ERR_H

#include "sylva/plugin.h"

#define PLUGIN_ERR_MAX 1024

typedef struct plugin_err {
    int status;                /* a negative sylva_status; 0 until a failure is reported */
    const sylva_params *where; /* the block holding `param`, or NULL; borrowed */
    char param[64];            /* the key at fault, or "" */
    char msg[PLUGIN_ERR_MAX];  /* the sentence; "" until a failure is reported */
} plugin_err;

/* Sets the sentence (printf-style; e may be NULL) and returns `status`, for
 * `return plugin_fail(err, SYLVA_ERR_NOMEM, "...")`. */
int plugin_fail(plugin_err *e, int status, const char *fmt, ...) SYLVA_PRINTF(3, 4);

/* The same for key `param` of the block `where` (NULL: no place known); the status is
 * SYLVA_ERR_PARAM. */
int plugin_fail_param(plugin_err *e, const sylva_params *where, const char *param, const char *fmt, ...)
    SYLVA_PRINTF(4, 5);

/* The same with any status (e.g. SYLVA_ERR_LIMIT at the key whose value passes a limit); param
 * may be NULL or "" (no key at fault). */
int plugin_fail_key(plugin_err *e, int status, const sylva_params *where, const char *param, const char *fmt, ...)
    SYLVA_PRINTF(5, 6);

#endif
