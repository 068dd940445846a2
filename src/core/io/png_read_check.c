/* png_read_check.c — a PNG read by libpng with handlers that keep its words for sylva's sentence
 * (png_read_check.h). */
#include "io/png_read_check.h"

#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/png_messages.h"
#include "util/chunk_check.h"

/* Reads the PNG open as f past its signature: its header and, with pixels, every row and the
 * chunks after them, expanded to 8 bits and RGB as OpenImageIO's reader has libpng do. */
static int read_png(FILE *f, const char *name, int pixels, err_buf *err)
{
    char message[PNG_MESSAGE_MAX] = "";
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, message, png_keep_error, png_ignore_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    unsigned char *volatile row = NULL; /* one row of the stored pixels; freed below (volatile: set after setjmp) */
    if (!png || !info) {
        png_destroy_read_struct(&png, &info, NULL);
        return err_nomem(err, "%s: out of memory for reading the PNG", name);
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, NULL);
        free(row);
        return err_fail(err, ERR_INPUT, "%s: the PNG is damaged or cut short (libpng says: %s)", name,
                        message[0] ? message : "it cannot be read");
    }
    png_init_io(png, f);
    png_set_sig_bytes(png, 8);
    png_read_info(png, info);
    if (pixels) {
        png_set_expand(png);
        int passes = png_set_interlace_handling(png);
        png_read_update_info(png, info);
        png_uint_32 height = png_get_image_height(png, info);
        size_t bytes = png_get_rowbytes(png, info);
        row = malloc(bytes ? bytes : 1);
        if (!row) {
            png_destroy_read_struct(&png, &info, NULL);
            return err_nomem(err, "%s: out of memory for a row of %zu bytes of the PNG", name, bytes);
        }
        for (int pass = 0; pass < passes; pass++)
            for (png_uint_32 y = 0; y < height; y++) png_read_row(png, row, NULL);
        png_read_end(png, NULL);
    }
    png_destroy_read_struct(&png, &info, NULL);
    free(row);
    return 0;
}

int png_read_check(const char *name, const void *bytes, size_t size, int pixels, err_buf *err)
{
    if (bytes && size < 8) return 0; /* too short for the signature: not a PNG */
    FILE *f = bytes ? fmemopen((void *)bytes, size, "rb") : fopen(name, "rb"); /* closed below */
    if (!f) return err_fail(err, ERR_INPUT, "%s: cannot read the file: %s", name, strerror(errno));
    unsigned char signature[8];
    int rc = 0;
    if (fread(signature, 1, sizeof signature, f) == sizeof signature && !png_sig_cmp(signature, 0, sizeof signature)) {
        rewind(f);
        rc = png_check_stream(f, name, err);
        if (!rc && fseek(f, 8, SEEK_SET) != 0) rc = err_fail(err, ERR_INPUT, "%s: cannot read the file", name);
        if (!rc) rc = read_png(f, name, pixels, err);
    }
    fclose(f);
    return rc;
}
