/* png_write.c — an RGB PNG through libpng at zlib level 1 (png_write.h). */
#include "io/png_write.h"

#include <png.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

#include "io/png_messages.h"

int png_write_xrgb(FILE *out, uint32_t width, uint32_t height, size_t stride, const uint8_t *pixels, err_buf *err)
{
    char message[PNG_MESSAGE_MAX] = "";
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, message, png_keep_error, png_ignore_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    /* one row of RGB; freed below (volatile: it is set after setjmp) */
    uint8_t *volatile row = malloc(width ? (size_t)width * 3 : 1);
    if (!png || !info || !row) {
        png_destroy_write_struct(&png, &info);
        free(row);
        return err_nomem(err, "out of memory for a PNG of %ux%u pixels", width, height);
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        free(row);
        return err_fail(err, ERR_OUTPUT, "writing the PNG failed: %s", message[0] ? message : "libpng error");
    }
    png_init_io(png, out);
    png_set_compression_level(png, 1);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE,
                 PNG_FILTER_TYPE_BASE);
    png_write_info(png, info);
    for (uint32_t y = 0; y < height; y++) {
        const uint8_t *src = pixels + (size_t)y * stride;
        for (uint32_t x = 0; x < width; x++) {
            uint32_t p;
            memcpy(&p, src + 4 * (size_t)x, sizeof p);
            row[3 * x] = (uint8_t)(p >> 16), row[3 * x + 1] = (uint8_t)(p >> 8), row[3 * x + 2] = (uint8_t)p;
        }
        png_write_row(png, row);
    }
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    free(row);
    if (fflush(out)) return err_fail(err, ERR_OUTPUT, "writing the PNG failed: %s", "the stream could not be flushed");
    return 0;
}
