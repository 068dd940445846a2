/* test_povray_run.c — POV-Ray's antialiasing options for sylva's sample counts, and the
 * message when POV-Ray cannot be found (no POV-Ray needed). */
#include "crosscheck/povray_run.h"
#include "harness.h"

TEST(antialias_options_match_the_samples)
{
    char o[64];
    povray_antialias_options(1, o, sizeof o);
    CHECK(!strcmp(o, "-A"));
    povray_antialias_options(3, o, sizeof o);
    CHECK(!strcmp(o, "-A"));
    povray_antialias_options(4, o, sizeof o);
    CHECK(!strcmp(o, "+A0.0 +AM1 +R2 -J"));
    povray_antialias_options(32, o, sizeof o);
    CHECK(!strcmp(o, "+A0.0 +AM1 +R5 -J"));
    povray_antialias_options(36, o, sizeof o);
    CHECK(!strcmp(o, "+A0.0 +AM1 +R6 -J"));
}

TEST(missing_povray_is_reported)
{
    povray_job job = {.folder = "/tmp", .scene = "none.pov", .output = "none.exr", .log = "sylva-test-none.log",
                      .executable = "/nonexistent/povray", .width = 4, .height = 4, .spp = 1};
    povray_result r;
    err_buf err = {{0}};
    CHECK_INT(povray_render(&job, &r, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "/nonexistent/povray");
    CHECK_STR_CONTAINS(err.msg, "SYLVA_POVRAY");
    remove("/tmp/sylva-test-none.log");
    job.executable = "povray";
    job.scene = "a\"b.pov";
    CHECK_INT(povray_render(&job, &r, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "quotes");
}

TEST_LIST(TEST_CASE(antialias_options_match_the_samples), TEST_CASE(missing_povray_is_reported))
