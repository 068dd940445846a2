/* crown_calibrate.h — the crown proxies' reflectances (crown_proxy.h), calibrated before the
 * render so that the mean radiance of the pixels a species' envelopes cover equals what its full
 * plants give there. */
#ifndef SYLVA_CROWN_CALIBRATE_H
#define SYLVA_CROWN_CALIBRATE_H

#include "render/accel_types.h"
#include "render/integrator.h"
#include "util/err.h"

/* Calibrates the proxies' reflectances for ctx (its camera, lights and masks; its seed keys the
 * probe samples), as above. threads: workers. Returns 0, or -1 with err set. */
int crown_proxies_calibrate(accel *a, const render_ctx *ctx, unsigned threads, err_buf *err);

#endif
