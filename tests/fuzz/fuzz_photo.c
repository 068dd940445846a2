/* fuzz_photo.c — libFuzzer target for the photograph reader of the photomontage (io/photo.h):
 * each input is written to photo.jpg and read with photo_read() (OpenImageIO's readers, the
 * EXIF fields sylva takes: focal lengths, focal plane, GPS, time, orientation), then the sensor
 * width and the capture instant are asked for. The memory budget is set to 16 MiB
 * (SYLVA_MEMORY_LIMIT), so a header stating a huge image must be refused before its pixels are
 * allocated (the same check as at any budget; a small one keeps each input's decoding short, as
 * the decoded pixels add no paths to the reader). Reading must end in an upright plate of finite linear samples or an error
 * sentence: a crash, a sanitizer report, a leak, a hang or runaway memory is a finding. A run
 * in which no input was ever read (the seeds are photographs) fails at exit: the reader was not
 * working (its image module not found, say), and nothing was fuzzed. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "io/photo.h"
#include "fuzz_file.h"

#define TARGET "fuzz_photo"

static const char *photo_path; /* in the scratch folder (work_dir.h owns it) */
static unsigned long inputs, plates; /* inputs tried, and read into a plate */

static void check_some_read(void)
{
    if (inputs && !plates) {
        fprintf(stderr, "%s: none of the %lu inputs was read into a plate, not even the seeds: the photograph "
                "reader is not working here\n", TARGET, inputs);
        _exit(1);
    }
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    static char path[1200];
    photo_path = fuzz_scratch_path("photo.jpg", path, sizeof path);
    setenv("SYLVA_MEMORY_LIMIT", "16M", 1);
    atexit(check_some_read);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_write_file(TARGET, photo_path, data, size);
    inputs++;
    err_buf err = {{0}};
    photo p = {0};
    if (photo_read(photo_path, &p, &err)) {
        if (!err.msg[0]) fuzz_finding(TARGET, "reading failed without a message");
        return 0;
    }
    plates++;
    const photo_exif *x = &p.exif;
    if (!p.width || !p.height || !p.rgb) fuzz_finding(TARGET, "a plate without pixels");
    if (x->orientation < 1 || x->orientation > 8) fuzz_finding(TARGET, "an orientation outside 1..8 was taken");
    int transposed = x->orientation >= 5;
    if ((transposed ? p.height : p.width) != p.stored_width) fuzz_finding(TARGET, "upright size does not match");
    for (size_t i = 0; i < (size_t)p.width * p.height * 3; i++)
        if (!isfinite(p.rgb[i])) fuzz_finding(TARGET, "a sample is not finite");
    double width_mm;
    photo_sensor_source src = photo_sensor_width(&p, &width_mm);
    if (src != PHOTO_SENSOR_UNKNOWN && !(width_mm >= 1.0 && width_mm <= 100.0))
        fuzz_finding(TARGET, "a sensor width outside 1..100 mm was taken");
    char iso[32];
    (void)photo_exif_iso8601(x, iso);
    photo_free(&p);
    return 0;
}
