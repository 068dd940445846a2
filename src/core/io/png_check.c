/* png_check.c — a PNG's chunk lengths checked against the file's size (png_check.h). The
 * format: an 8-byte signature, then chunks of a 4-byte big-endian length, a 4-byte type, the
 * data and a 4-byte CRC, the last of type IEND. */
#include "io/png_check.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static const unsigned char png_signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

int png_check(const char *path, err_buf *err)
{
    FILE *f = fopen(path, "rb");
    if (!f) return err_fail(err, ERR_INPUT, "%s: cannot read the image: %s", path, strerror(errno));
    unsigned char head[8];
    int rc = 0;
    long size = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    if (size < 0 || fseek(f, 0, SEEK_SET) != 0) {
        rc = err_fail(err, ERR_INPUT, "%s: cannot read the image: %s", path, strerror(errno));
    } else if (fread(head, 1, 8, f) == 8 && !memcmp(head, png_signature, 8)) {
        for (uint64_t at = 8; at + 8 <= (uint64_t)size;) {
            if (fseek(f, (long)at, SEEK_SET) != 0 || fread(head, 1, 8, f) != 8) break;
            uint64_t length = (uint64_t)head[0] << 24 | (uint64_t)head[1] << 16 | (uint64_t)head[2] << 8 | head[3];
            uint64_t left = (uint64_t)size - at - 8;
            if (length + 4 > left) {
                char type[5];
                for (int k = 0; k < 4; k++) type[k] = head[4 + k] >= 0x20 && head[4 + k] < 0x7f ? (char)head[4 + k] : '?';
                type[4] = 0;
                rc = err_fail(err, ERR_INPUT, "%s: the PNG is damaged or cut short: chunk '%s' at byte %llu states "
                              "%llu bytes of data, and %llu bytes follow it", path, type, (unsigned long long)at,
                              (unsigned long long)length, (unsigned long long)(left >= 4 ? left - 4 : 0));
                break;
            }
            if (!memcmp(head + 4, "IEND", 4)) break;
            at += 12 + length;
        }
    }
    fclose(f);
    return rc;
}
