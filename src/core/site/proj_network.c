/* proj_network.c — the process-wide switch of PROJ's network access, through GDAL's setting
 * for its contexts and the environment variable PROJ reads for its own. */
#include "site/proj_network.h"

#include <stdlib.h>
#include <string.h>

#include <ogr_srs_api.h>
#include <proj.h>

static int started;
static int environment_wants;   /* 1: PROJ_NETWORK or proj.ini enabled it before the start */
static char *environment_value; /* PROJ_NETWORK as it was (malloc'ed), or NULL when unset */

/* What a fresh PROJ context decides from the environment and proj.ini. */
static int fresh_context_enabled(void)
{
    PJ_CONTEXT *ctx = proj_context_create();
    if (!ctx) return 0;
    int on = proj_context_is_network_enabled(ctx);
    proj_context_destroy(ctx);
    return on;
}

void proj_network_start(void)
{
    if (!started) {
        const char *v = getenv("PROJ_NETWORK");
        environment_value = v ? strdup(v) : NULL; /* kept for the process's life */
        environment_wants = fresh_context_enabled();
        started = 1;
    }
    proj_network_allow(0);
}

void proj_network_allow(int allow)
{
    int on = allow && environment_wants;
    if (on && environment_value) setenv("PROJ_NETWORK", environment_value, 1);
    else if (on) unsetenv("PROJ_NETWORK");
    else setenv("PROJ_NETWORK", "OFF", 1);
    OSRSetPROJEnableNetwork(on);
}

int proj_network_enabled(void)
{
    return OSRGetPROJEnableNetwork() || fresh_context_enabled();
}
