/* scene_estimate.c — shape sizes and the scene's mesh memory against the budget. */
#include "scene_file/scene_estimate.h"

#include <stdio.h>

#include "scene_file/shape_index.h"
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

/* The bytes of a shape that is built once, kept as the largest one's place when it is. */
typedef struct shape_tally {
    uint64_t bytes, triangles, largest;
    const char *file;
    uint32_t line, column;
} shape_tally;

static void tally_shape(shape_tally *t, const shape_spec *sh, const char *file, uint32_t line, uint32_t column)
{
    uint64_t b = shape_bytes(sh), v, tri;
    shape_counts(sh, &v, &tri);
    t->bytes += b, t->triangles += tri;
    if (b > t->largest) t->largest = b, t->file = file, t->line = line, t->column = column;
}

int scene_estimate_check(const scene_file *sf, err_buf *err)
{
    shape_tally t = {.file = sf->path, .line = 1, .column = 1};
    shape_index distinct = {0};
    uint64_t placements = 0;
    for (uint32_t i = 0; i < sf->n_objects; i++) {
        const object_spec *o = &sf->objects[i];
        placements += o->kind == OBJECT_GROUP ? sf->groups[o->group].n_parts : 1;
        if (o->kind != OBJECT_SHAPE) continue; /* models are counted as they are read */
        uint32_t known = distinct.count;
        int64_t k = shape_index_add(&distinct, &o->shape, o->material);
        if (k >= 0 && k < known) continue; /* built once: placed again as an instance */
        tally_shape(&t, &o->shape, o->file ? o->file : sf->path, o->line, o->column);
    }
    shape_index_free(&distinct);
    for (uint32_t g = 0; g < sf->n_groups; g++)
        for (uint32_t i = 0; i < sf->groups[g].n_parts; i++) {
            const object_spec *part = &sf->groups[g].parts[i];
            if (part->kind == OBJECT_SHAPE) tally_shape(&t, &part->shape, part->file ? part->file : sf->path,
                                                        part->line, part->column);
        }
    for (uint32_t i = 0; i < sf->n_species; i++) {
        const species_spec *sp = &sf->species[i];
        if (!sp->plugin) tally_shape(&t, &sp->shape, sf->path, sp->line, sp->column);
    }
    uint64_t placed = placements * OBJECT_PLACEMENT_BYTES;
    char what[200];
    snprintf(what, sizeof what, "building the scene's shapes (%llu triangles) and %llu placements of objects",
             (unsigned long long)t.triangles, (unsigned long long)placements);
    if (!memory_check(t.bytes + placed, what, err)) return 0;
    err_buf why = *err;
    if (placed > t.bytes && sf->n_objects) {
        const object_spec *o = &sf->objects[0];
        return err_set(err, "%s:%u:%u: %s; use fewer objects (about %u bytes a placement; the first is here)",
                       o->file ? o->file : sf->path, o->line, o->column, why.msg, OBJECT_PLACEMENT_BYTES);
    }
    return err_set(err, "%s:%u:%u: %s; use fewer objects or fewer sphere subdivisions (the "
                   "largest shape is here)", t.file, t.line, t.column, why.msg);
}
