/* png_write.h — an 8-bit RGB PNG written straight through libpng, quickly: zlib at level 1 and
 * no filter on any row (on a page's flat colours and text, smaller and cheaper than Sub). For
 * pictures sylva draws itself (a page's pixels from cairo), where writing fast matters more than
 * the last bytes of compression; images read or written in
 * other formats go through io/image_io.h. Nothing is allocated past the call.
 */
#ifndef SYLVA_PNG_WRITE_H
#define SYLVA_PNG_WRITE_H

#include <stdint.h>
#include <stdio.h>

#include "util/err.h"

/* Writes width x height pixels, each a native-endian 32-bit word 0x??RRGGBB (cairo's RGB24
 * and ARGB32 layouts; the top byte is ignored), rows stride bytes apart from the top, to out as
 * an 8-bit RGB PNG. Returns 0, or -1 with err set (the stream then holds a partial file). */
int png_write_xrgb(FILE *out, uint32_t width, uint32_t height, size_t stride, const uint8_t *pixels, err_buf *err);

#endif
