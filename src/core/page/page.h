/* page.h — a printed page drawn once and written twice: as a vector PDF whose page is the print
 * size, and as a PNG of the same page at the print resolution. The drawing is given as one
 * function over a cairo context whose units are millimetres from the page's top-left corner, so
 * the PDF and the PNG hold the same marks (text through page_text.h, pictures through
 * page_image.h). The PDF keeps text and lines as vectors; a picture is embedded at its pixels.
 *
 * Both files are written atomically and as one set (io/atomic_file.h). Nothing is kept. */
#ifndef SYLVA_PAGE_H
#define SYLVA_PAGE_H

#include <cairo.h>
#include <stdio.h>

#include "util/err.h"

typedef struct page_size {
    double width_mm, height_mm;
    double dpi;              /* pixels per inch of the PNG and of the pictures in the PDF */
} page_size;

/* Draws the page on cr (millimetres, origin top-left, y down). ctx is the caller's. Returns 0,
 * or -1 with err set. */
typedef int (*page_draw_fn)(cairo_t *cr, const page_size *size, void *ctx, err_buf *err);

/* The pixels of the page's PNG along a side of mm millimetres at dpi (rounded, at least 1). */
int page_pixels(double mm, double dpi);

/* Draws the page into the open streams pdf and png (either may be NULL); the caller owns and
 * closes them. Returns 0, or -1 with err set. */
int page_write_streams(const page_size *size, page_draw_fn draw, void *ctx, FILE *pdf, FILE *png, err_buf *err);

/* Draws the page into pdf_path and png_path (either may be NULL). Returns 0, or -1 with err set
 * and nothing written. */
int page_write(const page_size *size, page_draw_fn draw, void *ctx, const char *pdf_path, const char *png_path,
               err_buf *err);

#endif
