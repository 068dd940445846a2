/* planting_growth.c — the growth curve of a planted species through its variants' heights
 * (planting_growth.h). */
#include "scene_build/planting_growth.h"

/* Point k of the curve: k = 0 the origin, k = v + 1 variant v. */
static void curve_point(const scene *s, uint32_t sp_index, double full_grown_age, uint32_t k, double *age, double *h)
{
    if (!k) {
        *age = 0, *h = 0;
        return;
    }
    const prototype *pr = &s->prototypes[s->species[sp_index].first_prototype + k - 1];
    *age = pr->age * full_grown_age, *h = pr->height;
}

/* Segment k (1 to n_variants) of the curve, from point k - 1 to point k. */
typedef struct curve_segment {
    double a0, h0, a1, h1;
} curve_segment;

static curve_segment segment(const scene *s, uint32_t sp_index, double full_grown_age, uint32_t k)
{
    curve_segment g;
    curve_point(s, sp_index, full_grown_age, k - 1, &g.a0, &g.h0);
    curve_point(s, sp_index, full_grown_age, k, &g.a1, &g.h1);
    return g;
}

double planting_height_at(const scene *s, uint32_t sp_index, double full_grown_age, double age)
{
    uint32_t n = s->species[sp_index].n_variants;
    curve_segment g = {0};
    for (uint32_t k = 1; k <= n; k++)
        if (age <= (g = segment(s, sp_index, full_grown_age, k)).a1)
            return g.a1 > g.a0 ? g.h0 + (g.h1 - g.h0) * (age - g.a0) / (g.a1 - g.a0) : g.h1;
    return g.h1; /* past the full-grown variant: level */
}

double planting_age_for_height(const scene *s, uint32_t sp_index, double full_grown_age, double height)
{
    uint32_t n = s->species[sp_index].n_variants;
    /* the first segment reaching the height; not reached before it, height > h0, so h1 > h0 */
    for (uint32_t k = 1; k <= n; k++) {
        curve_segment g = segment(s, sp_index, full_grown_age, k);
        if (height <= g.h1) return g.a0 + (g.a1 - g.a0) * (height - g.h0) / (g.h1 - g.h0);
    }
    return -1;
}

double planting_tallest(const scene *s, uint32_t sp_index)
{
    const species *sp = &s->species[sp_index];
    double h = 0;
    for (uint32_t v = 0; v < sp->n_variants; v++)
        if (s->prototypes[sp->first_prototype + v].height > h) h = s->prototypes[sp->first_prototype + v].height;
    return h;
}
