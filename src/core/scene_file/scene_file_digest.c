/* scene_file_digest.c — a digest (64-bit FNV-1a) of what every render of a scene reads but its
 * camera: the YAML tree of every section but camera:, viewpoints: and study: (keys and values,
 * so comments and layout do not count), the bytes of the species files it includes, and the
 * objects and surveyed trees as placed (a layout CSV or a survey counts by what it placed). A
 * study keeps it beside each output to tell an output of this scene from one of an earlier
 * version (docs/study.md). Files the scene names by path (a DTM, a model, a saved forest) count
 * by their names only. */
#include "scene_file/scene_file_loader.h"

#include <stdio.h>
#include <string.h>

#define FNV_OFFSET 1469598103934665603ull
#define FNV_PRIME 1099511628211ull

static uint64_t fnv(uint64_t h, const void *bytes, size_t n)
{
    const unsigned char *p = bytes;
    for (size_t i = 0; i < n; i++) h = (h ^ p[i]) * FNV_PRIME;
    return h;
}

/* A string with its terminating NUL, so that "ab","c" and "a","bc" differ. */
static uint64_t fnv_text(uint64_t h, const char *s) { return fnv(h, s, strlen(s) + 1); }

static uint64_t node_digest(uint64_t h, const ynode *n)
{
    h = fnv(h, &n->kind, sizeof n->kind);
    if (n->kind == YNODE_SCALAR) return fnv(fnv_text(h, n->text), &n->quoted, sizeof n->quoted);
    for (uint32_t i = 0; n->kind == YNODE_SEQUENCE && i < n->n_items; i++) h = node_digest(h, n->items[i]);
    for (uint32_t i = 0; n->kind == YNODE_MAPPING && i < n->n_pairs; i++)
        h = node_digest(fnv_text(h, n->pairs[i].key), n->pairs[i].value);
    return h;
}

/* The bytes of the file at path, or its name alone when it cannot be read. */
static uint64_t file_digest(uint64_t h, const char *path)
{
    h = fnv_text(h, path);
    FILE *f = fopen(path, "rb");
    if (!f) return h;
    char buf[1 << 14];
    for (size_t n; (n = fread(buf, 1, sizeof buf, f));) h = fnv(h, buf, n);
    fclose(f);
    return h;
}

static uint64_t placed_digest(uint64_t h, const scene_file *sf)
{
    for (uint32_t i = 0; i < sf->n_objects; i++) {
        const object_spec *o = &sf->objects[i];
        h = fnv_text(h, o->name ? o->name : "");
        const double v[] = {o->position[0], o->position[1], o->position[2], o->rotation_deg[0], o->rotation_deg[1],
                            o->rotation_deg[2], o->scale[0], o->scale[1], o->scale[2], o->heading_deg,
                            o->height_above_ground, (double)o->base, (double)o->development};
        h = fnv(h, v, sizeof v);
    }
    for (uint32_t i = 0; i < sf->trees.n_trees; i++) {
        const tree_spec *t = &sf->trees.trees[i];
        const double v[] = {(double)t->species, t->position[0], t->position[1], t->height, t->crown, t->age};
        h = fnv(h, v, sizeof v);
    }
    return h;
}

int sf_digest(loader *L)
{
    static const char *const left_out[] = {"camera", "viewpoints", "study"};
    uint64_t h = FNV_OFFSET;
    for (uint32_t i = 0; i < L->root->n_pairs; i++) {
        const ynode_pair *pr = &L->root->pairs[i];
        int skip = 0;
        for (size_t k = 0; k < sizeof left_out / sizeof *left_out; k++) skip |= !strcmp(pr->key, left_out[k]);
        if (!skip) h = node_digest(fnv_text(h, pr->key), pr->value);
    }
    for (uint32_t i = 0; i < L->n_seen; i++) h = file_digest(h, L->seen[i].real);
    L->sf->digest = placed_digest(h, L->sf);
    return 0;
}
