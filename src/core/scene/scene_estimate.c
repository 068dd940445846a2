/* scene_estimate.c — shape sizes and the scene's mesh memory against the budget. */
#include "scene/scene_estimate.h"

#include <stdio.h>

#include "util/memory_budget.h"

void shape_counts(const shape_spec *s, uint64_t *vertices, uint64_t *triangles)
{
    uint64_t v = 0, t = 0;
    switch (s->kind) {
    case SHAPE_BOX: v = 24, t = 12; break;
    case SHAPE_QUAD: v = 4, t = 2; break;
    case SHAPE_DISK: {
        uint64_t seg = s->subdivisions ? s->subdivisions : 32;
        if (seg < 3) seg = 3;
        v = seg + 1, t = seg;
        break;
    }
    case SHAPE_SPHERE: {
        uint64_t four_l = (uint64_t)1 << (2 * (s->subdivisions < 16 ? s->subdivisions : 16));
        v = 10 * four_l + 2, t = 20 * four_l;
        break;
    }
    case SHAPE_MESH: v = s->n_vertices, t = s->n_triangles; break;
    }
    *vertices = v, *triangles = t;
}

static uint64_t shape_bytes(const shape_spec *s)
{
    uint64_t v, t;
    shape_counts(s, &v, &t);
    return v * SHAPE_VERTEX_BYTES + t * SHAPE_TRIANGLE_BYTES;
}

int scene_estimate_check(const scene_file *sf, err_buf *err)
{
    uint64_t total = 0, largest = 0, triangles = 0;
    const char *where = sf->path;
    uint32_t line = 1, column = 1;
    for (uint32_t i = 0; i < sf->n_objects; i++) {
        const object_spec *o = &sf->objects[i];
        if (o->kind != OBJECT_SHAPE) continue; /* models are counted as they are read */
        uint64_t b = shape_bytes(&o->shape), v, t;
        shape_counts(&o->shape, &v, &t);
        total += b, triangles += t;
        if (b > largest) largest = b, line = o->line, column = o->column;
    }
    for (uint32_t i = 0; i < sf->n_species; i++) {
        const species_spec *sp = &sf->species[i];
        if (sp->plugin) continue;
        uint64_t b = shape_bytes(&sp->shape), v, t;
        shape_counts(&sp->shape, &v, &t);
        total += b, triangles += t;
        if (b > largest) largest = b, line = sp->line, column = sp->column;
    }
    char what[160];
    snprintf(what, sizeof what, "building the scene's shapes (%llu triangles)",
             (unsigned long long)triangles);
    if (!memory_check(total, what, err)) return 0;
    err_buf why = *err;
    return err_set(err, "%s:%u:%u: %s; use fewer objects or fewer sphere subdivisions (the "
                   "largest shape is here)", where, line, column, why.msg);
}
