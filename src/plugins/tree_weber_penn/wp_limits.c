/* wp_limits.c — the caps of one model from the host's per-model limit and the memory budget
 * (wp_limits.h). */
#include "wp_limits.h"

#include "wp_host_mesh.h"

/* Leaf frames that N triangles allow. */
static size_t leaves_of(size_t triangles, uint32_t leaf_triangles)
{
    return leaf_triangles ? triangles / leaf_triangles : triangles;
}

void wp_caps_fit(uint32_t leaf_triangles, wp_fits fits, void *ctx, wp_caps *out)
{
    size_t n = WP_HOST_MESH_MAX_TRIANGLES;
    out->by_memory = 0;
    while (fits && n > WP_MIN_TRIANGLES &&
           !fits(ctx, (uint64_t)n * WP_BYTES_PER_TRIANGLE + (uint64_t)leaves_of(n, leaf_triangles) * WP_BYTES_PER_LEAF)) {
        n /= 2;
        out->by_memory = 1;
    }
    if (n < WP_MIN_TRIANGLES) n = WP_MIN_TRIANGLES;
    out->triangles = n;
    out->leaves = leaves_of(n, leaf_triangles);
}
