/* damaged_png.h — a PNG damaged inside, and what a call prints on stderr meanwhile: libpng prints
 * what it finds wrong on stderr unless its reader sets its own handlers, so a damaged PNG must be
 * refused in sylva's sentence alone. damaged_png_write writes a 96 x 64 RGB PNG of noise (through
 * cut_image.h's writer) whose last IDAT chunk has its zlib checksum altered and its chunk CRC made
 * right again, so that only decoding the pixels finds the damage. Header-only, for the test
 * executables. */
#ifndef SYLVA_TEST_DAMAGED_PNG_H
#define SYLVA_TEST_DAMAGED_PNG_H

#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "cut_image.h"
#include "harness.h"

static inline uint32_t damaged_png_crc(const uint8_t *p, size_t n)
{
    uint32_t c = 0xffffffffu;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++) c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
    }
    return ~c;
}

/* The damaged PNG's bytes into bytes (room for cap) and its path (static storage) into *path;
 * the count of bytes, 0 when it could not be made (the check fails). */
static inline size_t damaged_png_write(const char *name, uint8_t *bytes, size_t cap, const char **path)
{
    *path = cut_image_write(name, 1.0);
    FILE *f = fopen(*path, "rb");
    size_t n = f ? fread(bytes, 1, cap, f) : 0;
    if (f) fclose(f);
    size_t last = 0; /* the last IDAT chunk's start */
    for (size_t at = 8; at + 12 <= n;) {
        uint32_t len = (uint32_t)bytes[at] << 24 | (uint32_t)bytes[at + 1] << 16 | (uint32_t)bytes[at + 2] << 8 | bytes[at + 3];
        if (!memcmp(bytes + at + 4, "IDAT", 4)) last = at;
        if (len > n - at - 12) break;
        at += 12 + len;
    }
    CHECK(n > 0 && n < cap && last > 0);
    if (!(n > 0 && n < cap && last > 0)) return 0;
    uint32_t len = (uint32_t)bytes[last] << 24 | (uint32_t)bytes[last + 1] << 16 | (uint32_t)bytes[last + 2] << 8 | bytes[last + 3];
    bytes[last + 8 + len - 1] ^= 0x5a; /* the zlib stream's Adler-32 */
    uint32_t crc = damaged_png_crc(bytes + last + 4, 4 + len);
    for (int k = 0; k < 4; k++) bytes[last + 8 + len + k] = (uint8_t)(crc >> (24 - 8 * k));
    f = fopen(*path, "wb");
    CHECK(f && fwrite(bytes, 1, n, f) == n);
    if (f) fclose(f);
    return n;
}

/* Standard error sent to a file of the work folder from stderr_begin till stderr_end, which
 * restores it and returns the count of bytes written meanwhile (what was written is copied to
 * the real stderr, so the test's log shows it). */
static int stderr_saved = -1;
static inline void stderr_begin(void)
{
    fflush(stderr);
    int fd = open(work_path("stderr.txt"), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    stderr_saved = dup(2);
    CHECK(fd >= 0 && stderr_saved >= 0);
    if (fd >= 0) dup2(fd, 2), close(fd);
}

static inline long stderr_end(void)
{
    fflush(stderr);
    if (stderr_saved >= 0) dup2(stderr_saved, 2), close(stderr_saved), stderr_saved = -1;
    FILE *f = fopen(work_path("stderr.txt"), "rb");
    long n = 0;
    int c;
    while (f && (c = fgetc(f)) != EOF) fputc(c, stderr), n++;
    if (f) fclose(f);
    remove(work_path("stderr.txt"));
    return n;
}

#endif
