/* cut_image.h — an image file cut short, as a copy interrupted or a download broken off: a
 * 96 x 64 RGB image of noise (so that every part of the file carries pixels) written by
 * image_write_u8 in the format of `name`'s extension into the test's work folder, then cut to
 * `keep` of its bytes. Header-only, for the test executables. */
#ifndef SYLVA_TEST_CUT_IMAGE_H
#define SYLVA_TEST_CUT_IMAGE_H

#include <stdint.h>
#include <sys/stat.h>
#include <unistd.h>

#include "harness.h"
#include "work_dir.h"
#include "io/image_io.h"

/* The path of the cut file (static storage); the check fails when it cannot be made. */
static inline const char *cut_image_write(const char *name, double keep)
{
    static uint8_t rgb[96 * 64 * 3];
    uint32_t x = 12345;
    for (size_t i = 0; i < sizeof rgb; i++) x = x * 1103515245u + 12345u, rgb[i] = (uint8_t)(x >> 23);
    static char path[1200];
    snprintf(path, sizeof path, "%s/%s", work_dir(), name);
    err_buf err = {{0}};
    CHECK_INT(image_write_u8(path, 96, 64, 3, rgb, &err), 0);
    struct stat st;
    CHECK_INT(stat(path, &st), 0);
    CHECK_INT(truncate(path, (off_t)(st.st_size * keep)), 0);
    return path;
}

#endif
