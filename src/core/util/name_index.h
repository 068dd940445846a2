/* name_index.h — a hash index from names to numbers, so that finding a name among n costs the
 * same whether n is ten or a million (the scene loader's duplicate checks and references, the
 * scene graph's material lookup).
 *
 * The first number added under a name is the one kept and found: adding a name that is there
 * already changes nothing and returns the number it has.
 *
 * Ownership: the index owns its table (name_index_free releases it) but not the names: each
 * name must stay valid and unchanged while the index holds it. A zeroed name_index is a valid
 * empty index.
 */
#ifndef SYLVA_NAME_INDEX_H
#define SYLVA_NAME_INDEX_H

#include <stdint.h>

typedef struct name_index {
    const char **names;  /* cap slots, NULL where empty; owned (the strings are not) */
    uint32_t *numbers;   /* cap slots; owned */
    uint32_t cap;        /* 0 or a power of two, at least twice count */
    uint32_t count;
} name_index;

void name_index_free(name_index *ix); /* accepts a zeroed index; leaves it zeroed */

/* Adds name → number unless the name is there. Returns the number the name has afterwards
 * (number itself when it was added), or -1 when out of memory (the index is unchanged). */
int64_t name_index_add(name_index *ix, const char *name, uint32_t number);

/* The number of name, or -1 when the index does not hold it. */
int64_t name_index_find(const name_index *ix, const char *name);

#endif
