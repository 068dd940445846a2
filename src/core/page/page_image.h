/* page_image.h — a picture placed on a page at the page's print resolution: resampled (each
 * pixel the area-weighted mean of the source pixels under it) to the pixels its rectangle takes
 * at the page's dpi, so that the PDF embeds it at exactly that resolution and the PNG shows it
 * pixel for pixel. */
#ifndef SYLVA_PAGE_IMAGE_H
#define SYLVA_PAGE_IMAGE_H

#include <cairo.h>
#include <stdint.h>

#include "util/err.h"

typedef struct page_picture {
    uint32_t width, height;
    const uint8_t *rgb;      /* 8-bit sRGB, 3 per pixel, row 0 at the top; borrowed */
} page_picture;

/* Paints p into the rectangle (x, y, w, h) millimetres of cr at dpi. Returns 0, or -1 with err
 * set (out of memory). */
int page_image(cairo_t *cr, const page_picture *p, double x, double y, double w, double h, double dpi, err_buf *err);

/* A cairo image of w x h pixels from 8-bit sRGB (3 a pixel, row 0 at the top): owned by the
 * caller (cairo_surface_destroy); NULL when out of memory. */
cairo_surface_t *page_surface_rgb(const uint8_t *rgb, int w, int h);

/* Paints image s stretched over the rectangle (x, y, w, h) millimetres with filter (NEAREST:
 * each pixel a sharp block). */
void page_paint(cairo_t *cr, cairo_surface_t *s, double x, double y, double w, double h, cairo_filter_t filter);

#endif
