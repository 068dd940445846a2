/* scene_spring.c — fresh leaves and blossom on the scene's day (scene_spring.h). */
#include "scene/scene_spring.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "scene/scene_season.h"

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

int scene_apply_blossom(scene *s, const scene_file *sf, uint64_t *petals, err_buf *err)
{
    uint64_t added = 0;
    if (petals) *petals = 0;
    const uint32_t n = sf->n_species < s->n_species ? sf->n_species : s->n_species; /* before the petals */
    for (uint32_t i = 0; i < n; i++) {
        const species_spec *sp = &sf->species[i];
        blossom_params p;
        double day;
        if (!scene_blossom_params(&sp->phenology, sf->season.day, &p, &day)) continue;
        blossom_report rep;
        err_buf why = {{0}};
        if (blossom_add(s, i, &p, day, s->image.seed, &rep, &why)) {
            const struct flowering *b = &sp->phenology.blossom;
            return err_at(err, why.status, b->file, b->line, b->column, "species '%s': %s", sp->name, why.msg);
        }
        added += rep.petals;
    }
    if (petals) *petals = added;
    return 0;
}

int scene_apply_fresh_leaves(scene *s, const scene_file *sf, err_buf *err)
{
    for (uint32_t i = 0; i < sf->n_species && i < s->n_species; i++) {
        const phenology *p = &sf->species[i].phenology;
        double f = phenology_fresh_share(p, sf->season.day);
        if (f > 0 && scene_turn_leaves(s, i, "fresh", p->fresh_color, f, err)) return -1;
    }
    return 0;
}
