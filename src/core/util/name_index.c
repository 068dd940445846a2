/* name_index.c — open addressing with linear probing over a power-of-two table kept at most
 * half full; names hashed with 64-bit FNV-1a. */
#include "util/name_index.h"

#include <stdlib.h>
#include <string.h>

static uint64_t name_hash(const char *name)
{
    uint64_t h = 0xcbf29ce484222325u;
    for (const unsigned char *p = (const unsigned char *)name; *p; p++) h = (h ^ *p) * 0x100000001b3u;
    return h;
}

/* The slot that holds name, or the empty slot where it would go. cap must be non-zero. */
static uint32_t slot_of(const char *const *names, uint32_t cap, const char *name)
{
    uint32_t k = (uint32_t)name_hash(name) & (cap - 1);
    while (names[k] && strcmp(names[k], name)) k = (k + 1) & (cap - 1);
    return k;
}

static int grow(name_index *ix)
{
    if (ix->cap > UINT32_MAX / 4) return -1;
    uint32_t cap = ix->cap ? ix->cap * 2 : 16;
    const char **names = calloc(cap, sizeof *names);  /* replaces ix->names below */
    uint32_t *numbers = malloc(cap * sizeof *numbers); /* replaces ix->numbers below */
    if (!names || !numbers) {
        free(names), free(numbers);
        return -1;
    }
    for (uint32_t i = 0; i < ix->cap; i++)
        if (ix->names[i]) {
            uint32_t k = slot_of(names, cap, ix->names[i]);
            names[k] = ix->names[i], numbers[k] = ix->numbers[i];
        }
    free(ix->names), free(ix->numbers);
    ix->names = names, ix->numbers = numbers, ix->cap = cap;
    return 0;
}

int64_t name_index_add(name_index *ix, const char *name, uint32_t number)
{
    if (ix->cap) {
        uint32_t k = slot_of(ix->names, ix->cap, name);
        if (ix->names[k]) return ix->numbers[k];
    }
    if ((uint64_t)(ix->count + 1) * 2 > ix->cap && grow(ix)) return -1;
    uint32_t k = slot_of(ix->names, ix->cap, name);
    ix->names[k] = name, ix->numbers[k] = number;
    ix->count++;
    return number;
}

int64_t name_index_find(const name_index *ix, const char *name)
{
    if (!ix->cap || !name) return -1;
    uint32_t k = slot_of(ix->names, ix->cap, name);
    return ix->names[k] ? (int64_t)ix->numbers[k] : -1;
}

void name_index_free(name_index *ix)
{
    free(ix->names);
    free(ix->numbers);
    memset(ix, 0, sizeof *ix);
}
