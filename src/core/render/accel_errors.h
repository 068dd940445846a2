/* accel_errors.h — Embree's error record: Embree reports errors through a callback on whichever
 * thread meets them (its build workers included); the record keeps the first one, under a lock,
 * for the thread that owns the err_buf to report (accel_device_error).
 *
 * Ownership: an accel owns its record (accel.errors), made by accel_errors_new and freed by
 * accel_errors_free. */
#ifndef SYLVA_ACCEL_ERRORS_H
#define SYLVA_ACCEL_ERRORS_H

#include <embree3/rtcore.h>

#include "render/accel_types.h"
#include "util/err.h"

/* An empty record, or NULL when memory runs out. */
struct accel_errors *accel_errors_new(void);
/* Makes e the record of device's errors. */
void accel_errors_watch(struct accel_errors *e, RTCDevice device);
void accel_errors_free(struct accel_errors *e); /* accepts NULL */

/* The first error Embree reported on a's device since it was built, into err: returns -1 with
 * it, or 0 when there was none. Call it on the thread that owns err, after tracing. */
int accel_device_error(const accel *a, err_buf *err);

#endif
