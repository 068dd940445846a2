/* test_verification_sheet.c — the photomontage's visualisation Type (montage/verification_sheet.h,
 * TGN 06/19 Table 2): 4 only with the camera at its surveyed position, surveyed control points in
 * map coordinates and a match within VERIFIED_RMSE_DEG; 3, saying why, without a match, with the
 * EXIF's GPS or a fitted position, with local points, or with an RMSE over the bound. */
#include <math.h>
#include <string.h>

#include "harness.h"
#include "montage/verification_sheet.h"

/* A match on a 4000 pixel wide frame 40 degrees across (focal length 5495 px) with rmse_px. */
static camera_match match_of(double rmse_px, unsigned free)
{
    camera_match m = {.free = free, .n_points = 12, .rmse_px = rmse_px};
    m.camera = (camera_model){.fov_deg = 40, .width = 4000, .height = 3000};
    return m;
}

static int type_of(const scene_file *sf, const control_points *cp, const camera_match *m, const char **why)
{
    static char buf[256];
    verification_inputs in = {.sf = sf, .cp = cp, .match = m};
    return verification_type(&in, buf, sizeof buf, why);
}

TEST(surveyed_camera_and_points_are_type_4)
{
    scene_file sf;
    memset(&sf, 0, sizeof sf);
    control_points cp = {.n = 12, .map = 1};
    camera_match m = match_of(3.0, CAMERA_FREE_ANGLES | CAMERA_FREE(CAMERA_FOCAL)); /* 0.031 degrees */
    const char *why;
    CHECK_INT(type_of(&sf, &cp, &m, &why), 4);
    CHECK(strstr(why, "survey verifiable") != NULL);
    /* the bound: 0.05 degrees is 4.8 px at 5495 px */
    m = match_of(4.7, m.free);
    CHECK_INT(type_of(&sf, &cp, &m, &why), 4);
    m = match_of(4.9, m.free);
    CHECK_INT(type_of(&sf, &cp, &m, &why), 3);
    CHECK(strstr(why, "over the 0.05") != NULL);
}

TEST(anything_unverified_is_type_3)
{
    scene_file sf;
    memset(&sf, 0, sizeof sf);
    control_points cp = {.n = 12, .map = 1};
    camera_match m = match_of(1.0, CAMERA_FREE_ANGLES);
    const char *why;
    CHECK_INT(type_of(&sf, NULL, NULL, &why), 3);
    CHECK(strstr(why, "not matched") != NULL);
    m.free |= CAMERA_FREE_POSITION;
    CHECK_INT(type_of(&sf, &cp, &m, &why), 3);
    CHECK(strstr(why, "fit_position") != NULL);
    m.free = CAMERA_FREE_ANGLES;
    cp.map = 0;
    CHECK_INT(type_of(&sf, &cp, &m, &why), 3);
    CHECK(strstr(why, "local coordinates") != NULL);
    cp.map = 1;
    sf.photo.camera_from_exif = 1;
    CHECK_INT(type_of(&sf, &cp, &m, &why), 3);
    CHECK(strstr(why, "GPS") != NULL);
}

TEST_LIST(TEST_CASE(surveyed_camera_and_points_are_type_4), TEST_CASE(anything_unverified_is_type_3))
