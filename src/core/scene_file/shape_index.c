/* shape_index.c — equal shapes found by hashing their keys. */
#include "scene_file/shape_index.h"

#include <stdlib.h>
#include <string.h>

static uint64_t hash_bytes(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; i++) h = (h ^ b[i]) * 1099511628211ull;
    return h;
}

static uint64_t shape_hash(const shape_spec *sh, const char *material)
{
    uint64_t h = 1469598103934665603ull;
    h = hash_bytes(h, &sh->kind, sizeof sh->kind);
    h = hash_bytes(h, sh->size, sizeof sh->size);
    h = hash_bytes(h, &sh->radius, sizeof sh->radius);
    h = hash_bytes(h, &sh->subdivisions, sizeof sh->subdivisions);
    const void *arrays[3] = {sh->vertices, sh->uvs, sh->triangles};
    h = hash_bytes(h, arrays, sizeof arrays);
    return material ? hash_bytes(h, material, strlen(material)) : h;
}

static int same_shape(const shape_spec *a, const char *ma, const shape_spec *b, const char *mb)
{
    return a->kind == b->kind && !memcmp(a->size, b->size, sizeof a->size) && a->radius == b->radius &&
           a->subdivisions == b->subdivisions && a->vertices == b->vertices && a->n_vertices == b->n_vertices &&
           a->uvs == b->uvs && a->n_uvs == b->n_uvs && a->triangles == b->triangles &&
           a->n_triangles == b->n_triangles && (ma && mb ? !strcmp(ma, mb) : ma == mb);
}

/* The slot holding (sh, material), or the empty one where it goes. */
static uint32_t *slot_of(const shape_index *ix, const shape_spec *sh, const char *material)
{
    uint32_t mask = ix->cap - 1, k = (uint32_t)shape_hash(sh, material) & mask;
    while (ix->slots[k] && !same_shape(ix->shapes[ix->slots[k] - 1], ix->materials[ix->slots[k] - 1], sh, material))
        k = (k + 1) & mask;
    return &ix->slots[k];
}

/* Room for one more shape: the arrays grown (at powers of two) and the table rebuilt at twice
 * the size when it would be more than half full. */
static int make_room(shape_index *ix)
{
    uint32_t n = ix->count;
    if ((n & (n - 1)) == 0) {
        size_t want = (size_t)n * 2 + 1;
        const shape_spec **shapes = realloc(ix->shapes, want * sizeof *shapes);
        if (!shapes) return -1;
        ix->shapes = shapes;
        const char **materials = realloc(ix->materials, want * sizeof *materials);
        if (!materials) return -1;
        ix->materials = materials;
    }
    if (2 * ((uint64_t)n + 1) <= ix->cap) return 0;
    if (ix->cap >= (1u << 31)) return -1;
    uint32_t cap = ix->cap ? 2 * ix->cap : 16;
    uint32_t *slots = calloc(cap, sizeof *slots);
    if (!slots) return -1;
    free(ix->slots);
    ix->slots = slots, ix->cap = cap;
    for (uint32_t i = 0; i < n; i++) *slot_of(ix, ix->shapes[i], ix->materials[i]) = i + 1;
    return 0;
}

int64_t shape_index_add(shape_index *ix, const shape_spec *sh, const char *material)
{
    if (ix->cap) {
        uint32_t *slot = slot_of(ix, sh, material);
        if (*slot) return *slot - 1;
    }
    if (make_room(ix)) return -1;
    ix->shapes[ix->count] = sh, ix->materials[ix->count] = material;
    *slot_of(ix, sh, material) = ix->count + 1;
    return ix->count++;
}

void shape_index_free(shape_index *ix)
{
    free(ix->shapes), free(ix->materials), free(ix->slots);
    memset(ix, 0, sizeof *ix);
}
