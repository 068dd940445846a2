/* raster_canvas.h — a small 8-bit RGB canvas for charts and maps written as PNG: filled
 * rectangles and discs, thick lines, and text in a built-in 5 x 7 pixel font (upper-case
 * letters, digits and a little punctuation, < > = among it; lower case is drawn as upper case). Row 0 is the top.
 *
 * Ownership: a canvas owns its pixels; canvas_free releases them (accepts a zeroed canvas).
 */
#ifndef SYLVA_RASTER_CANVAS_H
#define SYLVA_RASTER_CANVAS_H

#include <stdint.h>

#include "util/err.h"

typedef struct canvas {
    uint32_t width, height;
    uint8_t *rgb; /* width * height * 3, row 0 at the top; owned */
} canvas;

/* Allocates a canvas filled with bg. Returns 0, or -1 with err set (size 0 or above 16384, or
 * out of memory). */
int canvas_init(canvas *c, uint32_t width, uint32_t height, const uint8_t bg[3], err_buf *err);
void canvas_free(canvas *c);

void canvas_pixel(canvas *c, int x, int y, const uint8_t rgb[3]);          /* clipped */
void canvas_rect(canvas *c, int x0, int y0, int x1, int y1, const uint8_t rgb[3]); /* inclusive */
void canvas_disc(canvas *c, double cx, double cy, double r, const uint8_t rgb[3]);
/* A line of the given width in pixels between two points. */
void canvas_line(canvas *c, double x0, double y0, double x1, double y1, double width, const uint8_t rgb[3]);
/* Text with its top-left corner at (x, y), each font pixel drawn as scale x scale. */
void canvas_text(canvas *c, int x, int y, const char *text, int scale, const uint8_t rgb[3]);
int canvas_text_width(const char *text, int scale); /* pixels */
#define CANVAS_TEXT_HEIGHT 7 /* font pixels, times scale */

/* Writes the canvas as a PNG (image_write_u8: a temporary name renamed into place). */
int canvas_write_png(const canvas *c, const char *path, err_buf *err);

/* A distinct colour for series i (cycles after 8). */
void canvas_series_color(uint32_t i, uint8_t rgb[3]);

#endif
