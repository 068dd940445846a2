/* lsys_texture.c — the bark and leaf textures of a species from the shared presets. */
#include "lsys_texture.h"

#include <stddef.h>

#include "bark_fractal.h"
#include "leaf_affine.h"

const char *const lsys_bark_texture_names[] = {"smooth", "scaly", "furrowed", "fissured", "off", NULL};
const char *const lsys_leaf_texture_names[] = {"beech", "maple", "spruce", "shrub", "willow", "off", NULL};

static const bark_fractal_preset bark_presets[LSYS_BARK_TEXTURE_OFF] = {
    BARK_FRACTAL_SMOOTH, BARK_FRACTAL_SCALY, BARK_FRACTAL_FURROWED, BARK_FRACTAL_FISSURED};
static const leaf_affine_preset leaf_presets[LSYS_LEAF_TEXTURE_OFF] = {
    LEAF_AFFINE_BEECH, LEAF_AFFINE_MAPLE, LEAF_AFFINE_SPRUCE, LEAF_AFFINE_SHRUB, LEAF_AFFINE_WILLOW};

void lsys_texture_bark(int bark, float *height, uint8_t *rgba)
{
    const uint32_t n = LSYS_BARK_TEXTURE_SIZE;
    bark_fractal_params p = bark_fractal_preset_params(bark_presets[bark >= 0 && bark < LSYS_BARK_TEXTURE_OFF ? bark : 0]);
    bark_fractal_heights(&p, n, n, height);
    bark_fractal_albedo(&p, n, n, height, rgba);
}

int lsys_texture_leaf(int leaf, uint8_t *rgba)
{
    const uint32_t n = LSYS_LEAF_TEXTURE_SIZE;
    leaf_affine_maps maps;
    leaf_affine_preset_maps(leaf_presets[leaf >= 0 && leaf < LSYS_LEAF_TEXTURE_OFF ? leaf : 0], &maps);
    if (leaf_affine_render(&maps, n, LSYS_LEAF_TEXTURE_SEED, rgba, NULL, 0)) return -1;
    for (size_t t = 0; t < (size_t)n * n; t++) rgba[4 * t + 3] = 255; /* the polygon is the outline */
    return 0;
}
