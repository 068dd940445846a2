/* vessel_texture.c — the bark (the shared fractal bark) and leaf (the shared affine-map leaf) of
 * a species, written as sRGB-encoded RGBA8. */
#include "vessel_texture.h"

#include "leaf_affine.h"
#include "tree_look.h"

#include <stddef.h>

/* --- bark ---------------------------------------------------------------------------------- */

void vessel_texture_bark(const vessel_params *p, uint8_t *rgba)
{
    tree_look_bark_texture(&p->bark, VESSEL_BARK_TEXTURE_SIZE, rgba);
}

/* --- leaves -------------------------------------------------------------------------------- */

int vessel_texture_leaf(const vessel_params *p, uint8_t *rgba)
{
    return leaf_affine_render(&p->leaf, VESSEL_LEAF_TEXTURE_SIZE, VESSEL_LEAF_TEXTURE_SEED, rgba, NULL, 0);
}
