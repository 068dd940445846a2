/* page_text.h — text set on a page by pango in the page's typeface (DejaVu Sans, fonts-dejavu-core;
 * fontconfig's nearest sans when it is absent): a size in points, regular or bold, wrapped to a
 * width, aligned left, centred or right. The metrics are not hinted, so the PDF and the PNG of a
 * page break their lines at the same words. */
#ifndef SYLVA_PAGE_TEXT_H
#define SYLVA_PAGE_TEXT_H

#include <cairo.h>

#define PAGE_FONT "DejaVu Sans"

typedef enum page_align { PAGE_LEFT = 0, PAGE_CENTRE = 1, PAGE_RIGHT = 2 } page_align;

typedef struct page_font {
    double size_pt;
    int bold;
    page_align align;
    double rgb[3];
    double halo;            /* > 0: a white outline this many millimetres wide under the text */
} page_font;

/* Sets text (UTF-8; pango markup when markup is 1) with its top at y between x and x + width
 * millimetres (width <= 0: unwrapped, x the anchor of the alignment). Returns the text's height
 * in millimetres. */
double page_text(cairo_t *cr, double x, double y, double width, const page_font *f, const char *text, int markup);

/* The width in millimetres text would take, unwrapped. */
double page_text_width(cairo_t *cr, const page_font *f, const char *text);

/* The width and height in millimetres text would take, unwrapped (as page_text sets it). */
void page_text_size(cairo_t *cr, const page_font *f, const char *text, double *w, double *h);

#endif
