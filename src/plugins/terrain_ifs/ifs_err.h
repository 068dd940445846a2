/* ifs_err.h — the terrain_ifs model's failure sentence. A failing model function fills an
 * ifs_err with one sentence (what is wrong, what would be valid) and returns a negative
 * sylva_status; the plugin hands the sentence to the host through api->error or
 * api->param_error. No allocation, so reporting works when memory is short. */
#ifndef TERRAIN_IFS_ERR_H
#define TERRAIN_IFS_ERR_H

#define IFS_ERR_MAX 768

typedef struct ifs_err {
    char msg[IFS_ERR_MAX]; /* "" until a failure is reported */
} ifs_err;

/* Sets the sentence (printf-style; e may be NULL) and returns `status`, a negative
 * sylva_status, for `return ifs_fail(err, SYLVA_ERR_IO, "...")`. */
int ifs_fail(ifs_err *e, int status, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

#endif
