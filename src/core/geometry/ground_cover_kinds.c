/* ground_cover_kinds.c — the ground's kinds from the terrain's node classes (ADAPTER: see
 * ground_cover_kinds.h). */
#include "geometry/ground_cover_kinds.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene/heightfield.h"

int cover_kind_table_new(const scene *s, cover_kind_table *t, err_buf *err)
{
    static const struct {
        const char *name;
        cover_kind kind;
    } names[] = {{"terrain_ifs grass", COVER_MEADOW}, {"terrain_ifs dry grass", COVER_MEADOW},
                 {"terrain_ifs scree", COVER_SCREE},  {"terrain_ifs rock", COVER_ROCK},
                 {"terrain_ifs snow", COVER_SNOW},    {"terrain_ifs water", COVER_WATER}};
    t->of_material = malloc(s->n_materials ? s->n_materials : 1);
    if (!t->of_material) return err_nomem(err, "out of memory for the ground cover's kinds");
    for (uint32_t m = 0; m < s->n_materials; m++) {
        t->of_material[m] = -1;
        for (size_t k = 0; k < sizeof names / sizeof names[0]; k++)
            if (!strcmp(s->materials[m].name, names[k].name)) t->of_material[m] = (int8_t)names[k].kind;
    }
    return 0;
}

void cover_kind_table_free(cover_kind_table *t)
{
    free(t->of_material);
    t->of_material = NULL;
}

/* The material id of the node nearest (x, y) on the finest grid covering it, or -1. */
static int32_t node_material(const sylva_heightfield *h, double x, double y)
{
    for (uint32_t k = h->n_levels; k-- > 0;) {
        sylva_heightfield l = heightfield_level_view(h, k);
        double fi = (x - l.x0) / l.dx, fj = (y - l.y0) / l.dy;
        if (fi < 0 || fj < 0 || fi > l.nx - 1 || fj > l.ny - 1) continue;
        if (!h->levels[k].material) return -1;
        return h->levels[k].material[(size_t)lround(fj) * l.nx + (size_t)lround(fi)];
    }
    double fi = (x - h->x0) / h->dx, fj = (y - h->y0) / h->dy;
    if (!h->material || fi < 0 || fj < 0 || fi > h->nx - 1 || fj > h->ny - 1) return -1;
    return h->material[(size_t)lround(fj) * h->nx + (size_t)lround(fi)];
}

void cover_kinds_at(const scene *s, const cover_kind_table *t, double x, double y, float w[COVER_KINDS])
{
    for (int k = 0; k < COVER_KINDS; k++) w[k] = 0;
    const sylva_heightfield *h = s->terrain;
    if (!h) return;
    double z;
    if (h->has_water && !heightfield_height(h, x, y, &z) && z <= h->water_level) {
        w[COVER_WATER] = 1;
        return;
    }
    int32_t m = node_material(h, x, y);
    if (m >= 0 && (uint32_t)m < s->n_materials && t->of_material[m] >= 0) w[t->of_material[m]] = 1;
}
