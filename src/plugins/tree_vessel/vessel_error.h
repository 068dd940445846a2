/* vessel_error.h — how the vessel model library reports a failure: one sentence saying what is
 * wrong and what would be valid, and the scene-file key it concerns (empty when none), so the
 * plugin can hand it to api->param_error at the key's place. No allocation. */
#ifndef VESSEL_ERROR_H
#define VESSEL_ERROR_H

#define VESSEL_ERR_MSG_MAX 512

/* What kind of failure; the values are those of sylva_status. */
typedef enum vessel_fault {
    VESSEL_FAULT_PARAM = -1, /* a parameter or request the model cannot use */
    VESSEL_FAULT_LIMIT = -3, /* a documented limit would be passed */
    VESSEL_FAULT_NOMEM = -4  /* an allocation failed */
} vessel_fault;

typedef struct vessel_err {
    vessel_fault fault;
    char param[64];               /* scene-file key at fault, or "" */
    char msg[VESSEL_ERR_MSG_MAX]; /* the sentence; "" when nothing failed */
} vessel_err;

/* Sets err (param may be NULL) and returns `fault`, for `return vessel_fail(err, ...)`. err may
 * be NULL. */
int vessel_fail(vessel_err *err, vessel_fault fault, const char *param, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

#endif
