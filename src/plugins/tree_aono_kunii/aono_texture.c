/* aono_texture.c — the tree's leaf and bark textures: the shared affine-map leaf (003 §2) and
 * fractal bark (003 §1) of the config's `leaf:` and `bark:` keys. */
#include "aono_mesh.h"
#include "tree_look.h"

int aono_leaf_texture(const aono_config *cfg, uint8_t *rgba)
{
    return leaf_affine_render(&cfg->leaf, AONO_LEAF_TEXTURE_SIZE, AONO_LEAF_TEXTURE_SEED, rgba, NULL, 0);
}

int aono_bark_texture(const aono_config *cfg, uint8_t *rgba)
{
    tree_look_bark_texture(&cfg->bark, AONO_BARK_TEXTURE_SIZE, rgba);
    return 0;
}
