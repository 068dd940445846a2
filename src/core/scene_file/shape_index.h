/* shape_index.h — which built-in shapes of a scene are one mesh: two shapes of the same kind
 * and keys (an inline mesh by its arrays, which the rows of a layout share) and the same
 * material name are one, so that the scene builds it once and the memory estimate counts it
 * once. A hash index: finding a shape among a million costs the same as among ten.
 *
 * Ownership: the index owns its arrays (shape_index_free releases them) but not the shapes or
 * material names, which must outlive it (they live in the scene file). A zeroed index is a valid
 * empty one. */
#ifndef SYLVA_SHAPE_INDEX_H
#define SYLVA_SHAPE_INDEX_H

#include <stdint.h>

#include "scene_file/scene_file_spec.h"

typedef struct shape_index {
    const shape_spec **shapes;  /* count of them, in the order added; owned array */
    const char **materials;     /* beside shapes: the material's name, or NULL; owned array */
    uint32_t *slots;            /* cap slots: a shape's number + 1, 0 where empty; owned */
    uint32_t count, cap;        /* cap: 0 or a power of two, at least twice count */
} shape_index;

void shape_index_free(shape_index *ix); /* accepts a zeroed index; leaves it zeroed */

/* The number of the shape (sh, material): the one it has when an equal shape is there, else
 * count, the shape added. -1 when out of memory (the index unchanged). */
int64_t shape_index_add(shape_index *ix, const shape_spec *sh, const char *material);

#endif
