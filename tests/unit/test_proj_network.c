/* test_proj_network.c — PROJ's network access stays off whatever the environment asks
 * (site/proj_network.h): PROJ_NETWORK=ON, or network = on in a proj.ini found through
 * PROJ_DATA, enables it for every PROJ context, GDAL's own (the warper's) among them, until
 * sylva's start-up shuts it; --allow-gdal-virtual gives the environment's choice back. */
#include <proj.h>
#include <ogr_srs_api.h>

#include "harness.h"
#include "site/proj_network.h"
#include "work_dir.h"

static int fresh_context_enabled(void)
{
    PJ_CONTEXT *ctx = proj_context_create();
    int on = ctx && proj_context_is_network_enabled(ctx);
    proj_context_destroy(ctx);
    return on;
}

/* Every kind of context is offline after the start-up, and online again when allowed. */
static void check_start_shuts_the_network(void)
{
    proj_network_start();
    CHECK_INT(OSRGetPROJEnableNetwork(), 0); /* the contexts GDAL makes (one per thread) */
    CHECK_INT(fresh_context_enabled(), 0);   /* a context made through PROJ itself */
    CHECK_INT(proj_network_enabled(), 0);
    proj_network_allow(1);
    CHECK_INT(OSRGetPROJEnableNetwork(), 1);
    CHECK_INT(fresh_context_enabled(), 1);
    proj_network_allow(0);
    CHECK_INT(proj_network_enabled(), 0);
}

TEST(environment_variable_on)
{
    setenv("PROJ_NETWORK", "ON", 1);
    CHECK_INT(fresh_context_enabled(), 1); /* what PROJ would do on its own */
    check_start_shuts_the_network();
}

TEST(proj_ini_network_on)
{
    unsetenv("PROJ_NETWORK");
    char ini[1200];
    snprintf(ini, sizeof ini, "%s/proj.ini", work_dir());
    FILE *f = fopen(ini, "w");
    CHECK(f != NULL);
    if (!f) return;
    fprintf(f, "[general]\nnetwork = on\n");
    fclose(f);
    setenv("PROJ_DATA", work_dir(), 1);
    setenv("PROJ_LIB", work_dir(), 1);
    CHECK_INT(fresh_context_enabled(), 1);
    check_start_shuts_the_network();
}

TEST_LIST(TEST_CASE(environment_variable_on), TEST_CASE(proj_ini_network_on))
