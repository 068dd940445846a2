/* page_placer.h — where a map's labels go: each label set beside its mark at the first of eight
 * places round it (right, left, above, below, then the four corners) that overlaps no mark or
 * label placed before and stays within the map, else at the place that overlaps least. Marks and
 * labels are boxes in the page's millimetres; the order they are given in decides, so the same
 * map places the same way.
 *
 * Ownership: the placer owns its boxes; page_placer_free releases them. */
#ifndef SYLVA_PAGE_PLACER_H
#define SYLVA_PAGE_PLACER_H

#include <stdint.h>

typedef struct page_box {
    double x0, y0, x1, y1;   /* millimetres, x0 <= x1, y0 <= y1 */
} page_box;

typedef struct page_placer {
    page_box bounds;         /* where labels may go */
    page_box *boxes;         /* n taken: marks and labels; owned */
    uint32_t n, cap;
    int failed;              /* out of memory: later boxes are not kept (labels may then overlap) */
} page_placer;

void page_placer_init(page_placer *pl, page_box bounds);
void page_placer_free(page_placer *pl); /* accepts a zeroed one */

/* Takes the box round a mark of radius r at (x, y), for labels to keep off. */
void page_placer_mark(page_placer *pl, double x, double y, double r);

/* Takes a box as it is (a label placed by hand). */
void page_placer_take(page_placer *pl, page_box b);

/* Places a label w x h millimetres beside the mark of radius r at (x, y), gap millimetres from it,
 * takes its box and returns it. */
page_box page_placer_put(page_placer *pl, double x, double y, double r, double gap, double w, double h);

#endif
