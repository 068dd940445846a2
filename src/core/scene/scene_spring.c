/* scene_spring.c — fresh leaves and blossom on the scene's day (scene_spring.h). */
#include "scene/scene_spring.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

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

/* Fresh copies of species sp's leaf materials: albedo share f of the way from summer to c. */
static int freshen_species(scene *s, uint32_t sp, const double c[3], double f, err_buf *err)
{
    const uint32_t n = s->n_materials;
    int32_t *fresh = malloc((n ? n : 1) * sizeof *fresh); /* material id → its fresh copy, or -1; owned here */
    if (!fresh) return err_nomem(err, "out of memory for the fresh leaves of '%s'", s->species[sp].name);
    for (uint32_t k = 0; k < n; k++) fresh[k] = -1;
    const species *spc = &s->species[sp];
    int rc = 0;
    for (uint32_t v = 0; v < spc->n_variants && !rc; v++) {
        mesh *m = s->prototypes[spc->first_prototype + v].mesh;
        for (uint32_t t = 0; t < m->nt && !rc; t++) {
            uint32_t id = scene_triangle_material(s, m, t);
            if (id >= n || s->materials[id].bsdf != SYLVA_BSDF_LEAF) continue;
            if (fresh[id] < 0) {
                const material summer = s->materials[id]; /* a copy: adding a material may move the array */
                char name[256];
                snprintf(name, sizeof name, "%s (%s, fresh)", summer.name, spc->name);
                sylva_material_desc d = {.size = sizeof d, .name = name, .bsdf = SYLVA_BSDF_LEAF,
                                         .texture = summer.texture, .alpha_mask = summer.alpha_mask};
                const float a[3] = {summer.albedo.x, summer.albedo.y, summer.albedo.z},
                            tr[3] = {summer.transmittance.x, summer.transmittance.y, summer.transmittance.z};
                for (int k = 0; k < 3; k++) {
                    double albedo = a[k] + f * (c[k] - a[k]), through = a[k] > 0 ? tr[k] * albedo / a[k] : tr[k];
                    d.albedo[k] = (float)albedo, d.transmittance[k] = (float)fmin(through, 1 - albedo);
                }
                if ((fresh[id] = scene_add_material(s, &d, err)) < 0) rc = -1;
            }
            if (!rc) m->mat[t] = fresh[id];
        }
    }
    free(fresh);
    return rc;
}

int scene_apply_fresh_leaves(scene *s, const scene_file *sf, err_buf *err)
{
    for (uint32_t i = 0; i < sf->n_species && i < s->n_species; i++) {
        const phenology *p = &sf->species[i].phenology;
        double f = phenology_fresh_share(p, sf->season.day);
        if (f > 0 && freshen_species(s, i, p->fresh_color, f, err)) return -1;
    }
    return 0;
}
