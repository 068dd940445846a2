/* wp_limits.h — how large one tree_weber_penn model may grow: at most the host's triangles per
 * model (WP_HOST_MESH_MAX_TRIANGLES), fewer when the memory budget cannot hold that many. The caps are
 * handed to wp_model_grow (stem triangles, leaves), which stops a tree that would pass them, and
 * the whole model (stem triangles plus the leaves' triangles) is held to the same count.
 *
 * A model of N triangles costs about WP_BYTES_PER_TRIANGLE bytes each at its peak (the grown
 * model's vertices, uv and triangles in double precision, the plugin's single-precision copy
 * and the host's mesh with normals) plus WP_BYTES_PER_LEAF per leaf frame. The budget is asked
 * through a `fits` callback (the host's memory_check); the count is halved from the host's
 * limit until it fits, or down to WP_MIN_TRIANGLES. */
#ifndef WP_LIMITS_H
#define WP_LIMITS_H

#include <stddef.h>
#include <stdint.h>

#define WP_BYTES_PER_TRIANGLE 120u
#define WP_BYTES_PER_LEAF 96u
#define WP_MIN_TRIANGLES 65536u

typedef struct wp_caps {
    size_t triangles;      /* of the whole model: stems and leaves */
    size_t leaves;         /* leaf frames: triangles / the leaf's triangles */
    int by_memory;         /* 1 when the budget, not the host's per-model limit, set triangles */
} wp_caps;

/* Whether `bytes` fit the memory budget (1) or not (0). */
typedef int (*wp_fits)(void *ctx, uint64_t bytes);

/* The caps for a leaf of `leaf_triangles` triangles (0: no leaves drawn); fits NULL: no budget
 * but the host's per-model limit. */
void wp_caps_fit(uint32_t leaf_triangles, wp_fits fits, void *ctx, wp_caps *out);

#endif
