/* eco_err.h — how the ecology model reports a failure: a sylva_status, one sentence (what is
 * wrong, what would be valid) and, when a scene-file key is at fault, the block and the key, so
 * that the plugin file hands it to api->param_error at the key's place (else api->error). The
 * model never calls the host itself. No allocation, so reporting works when memory is short. */
#ifndef ECO_ERR_H
#define ECO_ERR_H

#include "sylva/plugin.h"

#define ECO_ERR_MAX 768

typedef struct eco_err {
    int status;                /* a negative sylva_status; 0 until a failure is reported */
    const sylva_params *where; /* the block holding `param`, or NULL; borrowed */
    char param[64];            /* the key at fault, or "" */
    char msg[ECO_ERR_MAX];     /* the sentence; "" until a failure is reported */
} eco_err;

/* Sets the sentence (printf-style; e may be NULL) and returns `status`, for
 * `return eco_fail(err, SYLVA_ERR_NOMEM, "...")`. */
int eco_fail(eco_err *e, int status, const char *fmt, ...) SYLVA_PRINTF(3, 4);

/* The same for a key of a scene-file block (`where` may be NULL: no place known). */
int eco_fail_param(eco_err *e, const sylva_params *where, const char *param, const char *fmt, ...)
    SYLVA_PRINTF(4, 5);

#endif
