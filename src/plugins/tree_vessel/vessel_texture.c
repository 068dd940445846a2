/* vessel_texture.c — the bark (the shared fractal bark, one preset per kind) and leaf outlines
 * (affine-map leaves from the shared presets), written as sRGB-encoded RGBA8. */
#include "vessel_texture.h"

#include "bark_fractal.h"
#include "leaf_affine.h"

#include <stddef.h>

/* --- bark ---------------------------------------------------------------------------------- */

/* The fractal bark (003 §1, bark_fractal.h) whose preset names the same look as the kind. */
static const bark_fractal_preset bark_presets[VESSEL_BARK_KINDS] = {
    [VESSEL_BARK_SMOOTH] = BARK_FRACTAL_SMOOTH,
    [VESSEL_BARK_SCALY] = BARK_FRACTAL_SCALY,
    [VESSEL_BARK_FURROWED] = BARK_FRACTAL_FURROWED,
    [VESSEL_BARK_FISSURED] = BARK_FRACTAL_FISSURED,
};

void vessel_texture_bark(vessel_bark_kind kind, uint8_t *rgba)
{
    const uint32_t n = VESSEL_BARK_TEXTURE_SIZE;
    bark_fractal_params p = bark_fractal_preset_params(bark_presets[(unsigned)kind < VESSEL_BARK_KINDS ? kind : 0]);
    float height[VESSEL_BARK_TEXTURE_SIZE]; /* one row at a time, at texel centres */
    for (uint32_t row = 0; row < n; row++) {
        double v = 1.0 - (row + 0.5) / n;
        for (uint32_t x = 0; x < n; x++) height[x] = (float)bark_fractal_height(&p, (x + 0.5) / n, v);
        bark_fractal_albedo(&p, n, 1, height, rgba + (size_t)row * n * 4);
    }
}

/* --- leaves -------------------------------------------------------------------------------- */

/* Each outline is an affine-map leaf (003 §2, leaf_affine.h) from the shared presets. */
int vessel_texture_leaf(vessel_leaf_shape shape, uint8_t *rgba)
{
    static const leaf_affine_preset preset[VESSEL_LEAF_SHAPES] = {
        [VESSEL_LEAF_SHAPE_OVATE] = LEAF_AFFINE_BEECH,
        [VESSEL_LEAF_SHAPE_NEEDLES] = LEAF_AFFINE_SPRUCE,
        [VESSEL_LEAF_SHAPE_LANCEOLATE] = LEAF_AFFINE_WILLOW,
        [VESSEL_LEAF_SHAPE_PALMATE] = LEAF_AFFINE_MAPLE,
    };
    leaf_affine_maps maps;
    leaf_affine_preset_maps(preset[(unsigned)shape < VESSEL_LEAF_SHAPES ? shape : 0], &maps);
    return leaf_affine_render(&maps, VESSEL_LEAF_TEXTURE_SIZE, VESSEL_LEAF_TEXTURE_SEED, rgba,
                              NULL, 0);
}
