/* vessel_texture.c — the bark (the shared fractal bark) and leaf (the shared affine-map leaf) of
 * a species, written as sRGB-encoded RGBA8. */
#include "vessel_texture.h"

#include "leaf_affine.h"
#include "tree_look.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

/* --- bark ---------------------------------------------------------------------------------- */

void vessel_texture_bark(const vessel_params *p, uint8_t *rgba)
{
    tree_look_bark_texture(&p->bark, VESSEL_BARK_TEXTURE_SIZE, rgba);
}

/* --- leaves -------------------------------------------------------------------------------- */

/* The spray: leaf k of n turned by (k / (n - 1) - 1/2) VESSEL_SPRAY_FAN about the stalk (u, v) =
 * (1/2, 0) and scaled by VESSEL_SPRAY_SCALE, drawn from the outermost pair inward so that the
 * middle leaf lies on top. */
int vessel_texture_leaf(const vessel_params *p, uint8_t *rgba)
{
    const uint32_t n = VESSEL_LEAF_TEXTURE_SIZE, leaves = p->leaf_spray;
    if (leaves <= 1) return leaf_affine_render(&p->leaf, n, VESSEL_LEAF_TEXTURE_SEED, rgba, NULL, 0);
    uint8_t *leaf = malloc((size_t)n * n * 4); /* owned here */
    if (!leaf || leaf_affine_render(&p->leaf, n, VESSEL_LEAF_TEXTURE_SEED, leaf, NULL, 0)) {
        free(leaf);
        return -1;
    }
    memset(rgba, 0, (size_t)n * n * 4);
    for (uint32_t j = 0; j < leaves; j++) {
        uint32_t k = j % 2 ? leaves - 1 - j / 2 : j / 2; /* 0, n-1, 1, n-2, ... */
        double a = ((double)k / (leaves - 1) - 0.5) * VESSEL_SPRAY_FAN * (M_PI / 180.0);
        double c = cos(a), s = sin(a);
        for (uint32_t row = 0; row < n; row++)
            for (uint32_t x = 0; x < n; x++) {
                double du = (x + 0.5) / n - 0.5, dv = 1.0 - (row + 0.5) / n;
                double pu = 0.5 + (c * du + s * dv) / VESSEL_SPRAY_SCALE, pv = (c * dv - s * du) / VESSEL_SPRAY_SCALE;
                if (!(pu >= 0 && pu < 1 && pv >= 0 && pv < 1)) continue;
                const uint8_t *src = leaf + 4 * ((size_t)(n - 1 - (uint32_t)(pv * n)) * n + (uint32_t)(pu * n));
                if (src[3] > 127) memcpy(rgba + 4 * ((size_t)row * n + x), src, 4);
            }
    }
    free(leaf);
    return 0;
}
