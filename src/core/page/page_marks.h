/* page_marks.h — the marks every map on a page carries, drawn as vectors in millimetres: a north
 * arrow and a scale bar of a round length (1, 2 or 5 times a power of ten metres). */
#ifndef SYLVA_PAGE_MARKS_H
#define SYLVA_PAGE_MARKS_H

#include <cairo.h>
#include <stddef.h>

/* A north arrow `size` millimetres tall with its foot at (x, y), pointing up the page. */
void page_north_arrow(cairo_t *cr, double x, double y, double size);

/* A scale bar at most max_mm long with its left end at (x, y) for a map of mm_per_m millimetres
 * a metre, its length written under it. Returns the bar's length in millimetres. */
double page_scale_bar(cairo_t *cr, double x, double y, double max_mm, double mm_per_m);

/* A dot of radius r millimetres at (x, y) filled with rgb and ringed in white (a map's marker). */
void page_dot(cairo_t *cr, double x, double y, double r, const double rgb[3]);

/* The round length (1, 2 or 5 times a power of ten) at most `most`. */
double page_round_length(double most);

/* A length in metres as text: "500 m", "2 km", "2.5 km". */
void page_length_text(double metres, char *out, size_t n);

#endif
