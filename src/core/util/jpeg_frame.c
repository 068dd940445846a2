/* jpeg_frame.c — a JPEG's frame size from its markers (jpeg_frame.h). A JPEG is the SOI marker
 * (FF D8), then segments: a marker (FF, any number of FF fill bytes, a code), and for all but
 * the standalone codes (01, D0-D7) a 2-byte big-endian length that counts itself and the
 * payload. A start of frame (C0-C3, C5-C7, C9-CB, CD-CF) holds the sample precision, the
 * height, the width and the number of components; the scans (SOS, DA) come after it. */
#include "util/jpeg_frame.h"

#include <stdio.h>

/* 1 when code is a start-of-frame marker (SOF0-SOF15 but DHT C4, JPG C8 and DAC CC). */
static int is_frame(int code)
{
    return code >= 0xC0 && code <= 0xCF && code != 0xC4 && code != 0xC8 && code != 0xCC;
}

/* The next marker's code from f's position, or -1 at the end of the file. As libjpeg does, bytes
 * before the marker that are not FF are skipped (a damaged segment length leaves some; libjpeg
 * only warns of them), as are FF fill bytes and FF 00 (a stuffed zero, not a marker). */
static int next_marker(FILE *f)
{
    for (;;) {
        int c;
        while ((c = fgetc(f)) != 0xFF)
            if (c == EOF) return -1;
        while ((c = fgetc(f)) == 0xFF) {}
        if (c == EOF) return -1;
        if (c != 0) return c;
    }
}

int jpeg_frame(const char *path, uint32_t *width, uint32_t *height, uint32_t *components)
{
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    int found = 0;
    if (fgetc(f) == 0xFF && fgetc(f) == 0xD8) {
        for (int code; !found && (code = next_marker(f)) >= 0;) {
            if (code == 0x01 || (code >= 0xD0 && code <= 0xD7)) continue; /* standalone */
            if (code == 0xD9 || code == 0xDA) break; /* end of image, start of scan */
            unsigned char b[8];
            if (fread(b, 1, 2, f) != 2) break;
            long length = (long)b[0] << 8 | b[1];
            if (is_frame(code)) {
                if (fread(b, 1, 6, f) != 6) break;
                *height = (uint32_t)b[1] << 8 | b[2];
                *width = (uint32_t)b[3] << 8 | b[4];
                *components = b[5];
                found = 1;
            } else if (length > 2 && fseek(f, length - 2, SEEK_CUR) != 0) {
                break; /* a length below 2 skips nothing, as in libjpeg */
            }
        }
    }
    fclose(f);
    return found;
}
