/* accel_errors.c — the first error Embree reported on a device (accel_errors.h). */
#include "render/accel_errors.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The first error Embree reported on the device. Embree calls the callback from any thread,
 * so the record is taken under a lock and read under it. */
struct accel_errors {
    pthread_mutex_t lock;
    enum RTCError code;        /* RTC_ERROR_NONE until the first error */
    char message[256];
};

static void embree_error(void *user, enum RTCError code, const char *str)
{
    struct accel_errors *e = user;
    pthread_mutex_lock(&e->lock);
    if (e->code == RTC_ERROR_NONE && code != RTC_ERROR_NONE) {
        e->code = code;
        snprintf(e->message, sizeof e->message, "%s", str ? str : "");
    }
    pthread_mutex_unlock(&e->lock);
}

struct accel_errors *accel_errors_new(void)
{
    struct accel_errors *e = calloc(1, sizeof *e);
    if (e) pthread_mutex_init(&e->lock, NULL);
    return e;
}

void accel_errors_watch(struct accel_errors *e, RTCDevice device)
{
    rtcSetDeviceErrorFunction(device, embree_error, e);
}

void accel_errors_free(struct accel_errors *e)
{
    if (e) pthread_mutex_destroy(&e->lock);
    free(e);
}

int accel_device_error(const accel *a, err_buf *err)
{
    struct accel_errors *e = a->errors;
    if (!e) return 0;
    pthread_mutex_lock(&e->lock);
    enum RTCError code = e->code;
    char message[sizeof e->message];
    memcpy(message, e->message, sizeof message);
    pthread_mutex_unlock(&e->lock);
    if (code == RTC_ERROR_NONE) return 0;
    if (code == RTC_ERROR_OUT_OF_MEMORY) return err_nomem(err, "out of memory in Embree: %s", message);
    return err_set(err, "Embree error %d: %s", (int)code, message);
}
