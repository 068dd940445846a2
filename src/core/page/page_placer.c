/* page_placer.c — labels beside their marks, clear of one another (page_placer.h). */
#include "page/page_placer.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void page_placer_init(page_placer *pl, page_box bounds)
{
    memset(pl, 0, sizeof *pl);
    pl->bounds = bounds;
}

void page_placer_free(page_placer *pl)
{
    free(pl->boxes);
    memset(pl, 0, sizeof *pl);
}

void page_placer_take(page_placer *pl, page_box b)
{
    if (pl->failed) return;
    if (pl->n == pl->cap) {
        uint32_t cap = pl->cap ? 2 * pl->cap : 32;
        page_box *grown = realloc(pl->boxes, cap * sizeof *grown);
        if (!grown) {
            pl->failed = 1;
            return;
        }
        pl->boxes = grown, pl->cap = cap;
    }
    pl->boxes[pl->n++] = b;
}

void page_placer_mark(page_placer *pl, double x, double y, double r)
{
    page_placer_take(pl, (page_box){x - r, y - r, x + r, y + r});
}

static double overlap(const page_box *a, const page_box *b)
{
    double w = fmin(a->x1, b->x1) - fmax(a->x0, b->x0), h = fmin(a->y1, b->y1) - fmax(a->y0, b->y0);
    return w > 0 && h > 0 ? w * h : 0;
}

/* What a label at b costs: the area it overlaps other boxes by, and ten times the area it spills
 * out of the bounds by. */
static double cost_of(const page_placer *pl, const page_box *b)
{
    double c = 0;
    for (uint32_t k = 0; k < pl->n; k++) c += overlap(b, &pl->boxes[k]);
    double area = (b->x1 - b->x0) * (b->y1 - b->y0);
    return c + 10 * (area - overlap(b, &pl->bounds));
}

page_box page_placer_put(page_placer *pl, double x, double y, double r, double gap, double w, double h)
{
    double d = r + gap, s = M_SQRT1_2 * d;
    /* the label's top-left corner for each place: right, left, above, below, then the corners */
    const double at[8][2] = {{x + d, y - h / 2},      {x - d - w, y - h / 2}, {x - w / 2, y - d - h},
                             {x - w / 2, y + d},      {x + s, y - s - h},     {x + s, y + s},
                             {x - s - w, y - s - h},  {x - s - w, y + s}};
    page_box best = {0};
    double least = INFINITY;
    for (int k = 0; k < 8 && least > 0; k++) {
        page_box b = {at[k][0], at[k][1], at[k][0] + w, at[k][1] + h};
        double c = cost_of(pl, &b);
        if (c < least) least = c, best = b;
    }
    page_placer_take(pl, best);
    return best;
}
