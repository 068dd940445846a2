/* scene_spring.c — fresh leaves and blossom on the scene's day (scene_spring.h). */
#include "season/scene_spring.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "season/scene_season.h"

int scene_blossom_params(const phenology *ph, uint32_t day, blossom_params *p, double *clock_day)
{
    int since = phenology_blossom_day(ph, day);
    if (since < 0) return 0;
    const struct flowering *b = &ph->blossom;
    double length = (double)((b->last + 366 - b->first) % 366 + 1); /* days with open flowers */
    blossom_params_default(p);
    p->lifetime_max = 0.5 * length, p->lifetime_min = 0.25 * length;
    p->first_day = b->first, p->last_day = b->first + length - p->lifetime_max;
    p->per_point = b->per_point, p->max_per_plant = b->max_per_plant;
    p->size_max = 0.5 * b->size, p->size_min = 0.6 * p->size_max;
    for (int c = 0; c < 3; c++) p->colour_open[c] = (float)b->color[c], p->colour_faded[c] = (float)b->faded_color[c];
    *clock_day = b->first + since + 0.5;
    return 1;
}

int scene_apply_blossom(scene *s, uint32_t i, const phenology *ph, uint32_t day, const char *name,
                        err_buf *err)
{
    blossom_params p;
    double clock;
    if (!scene_blossom_params(ph, day, &p, &clock)) return 0;
    blossom_report rep;
    err_buf why = {{0}};
    if (!blossom_add(s, i, &p, clock, s->image.seed, &rep, &why)) return 0;
    const struct flowering *b = &ph->blossom;
    return err_at(err, why.status, b->file, b->line, b->column, "species '%s': %s", name, why.msg);
}

int scene_apply_fresh_leaves(scene *s, uint32_t i, const phenology *p, uint32_t day, err_buf *err)
{
    double f = phenology_fresh_share(p, day);
    return f > 0 ? scene_turn_leaves(s, i, "fresh", p->fresh_color, f, err) : 0;
}
