/* fuzz_control_points.c — libFuzzer target for the control-point reader of the camera match
 * (montage/control_points.h): each input is a control-point file, CSV or ImGRAFT's text, read
 * with control_points_read(). Reading must end in at least one point, every number finite, or
 * an error sentence: a crash, a sanitizer report, a leak, a hang or runaway memory is a
 * finding. */
#include <math.h>
#include <stdint.h>

#include "montage/control_points.h"
#include "fuzz_file.h"

#define TARGET "fuzz_control_points"

static const char *points_path; /* in the scratch folder (work_dir.h owns it) */

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    static char path[1200];
    points_path = fuzz_scratch_path("points.csv", path, sizeof path);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_write_file(TARGET, points_path, data, size);
    err_buf err = {{0}};
    control_points *cp = control_points_read(points_path, "points.csv", &err); /* owned here */
    if (!cp && !err.msg[0]) fuzz_finding(TARGET, "reading failed without a message");
    if (cp && cp->n == 0) fuzz_finding(TARGET, "a set without points was handed back");
    for (uint32_t i = 0; cp && i < cp->n; i++) {
        const control_point *p = &cp->points[i];
        if (!p->id || !p->id[0]) fuzz_finding(TARGET, "a point without an id");
        for (int k = 0; k < 3; k++)
            if (!isfinite(p->world[k]) || (k < 2 && !isfinite(p->pixel[k])))
                fuzz_finding(TARGET, "a point with a number that is not finite");
    }
    control_points_free(cp);
    return 0;
}
