/* tree_look.c — the `leaf:` and `bark:` keys of the tree plugins as leaf maps and bark
 * parameters (tree_look.h). Allocates nothing. */
#include "tree_look.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

const char *const tree_look_bark_names[BARK_FRACTAL_PRESETS + 1] = {
    [BARK_FRACTAL_SMOOTH] = "smooth",
    [BARK_FRACTAL_SCALY] = "scaly",
    [BARK_FRACTAL_FURROWED] = "furrowed",
    [BARK_FRACTAL_FISSURED] = "fissured",
    [BARK_FRACTAL_PRESETS] = NULL,
};

/* Whether text is meant as a name: its first non-blank character is a letter (maps start with
 * a number). */
static int names_something(const char *text)
{
    while (*text == ' ' || *text == '\t' || *text == '\n') text++;
    return !*text || (*text >= 'a' && *text <= 'z') || (*text >= 'A' && *text <= 'Z');
}

int tree_look_leaf(const char *text, uint32_t size, leaf_affine_maps *out, char *msg, size_t msg_size)
{
    if (!text) text = "";
    for (int p = 0; p < LEAF_AFFINE_PRESET_COUNT; p++)
        if (!strcmp(text, leaf_affine_preset_name((leaf_affine_preset)p))) {
            leaf_affine_preset_maps((leaf_affine_preset)p, out);
            return p;
        }
    if (names_something(text)) {
        snprintf(msg, msg_size, "'%.40s' is not a leaf; give a preset (beech, maple, spruce, shrub, "
                 "willow) or affine maps \"a b c d e f[ p]; ...\"", text);
        return -1;
    }
    char why[256];
    if (leaf_affine_parse(text, out, why, sizeof why)) {
        snprintf(msg, msg_size, "leaf maps: %s", why);
        return -1;
    }
    leaf_affine_raster raster = {0}; /* owned here */
    int rc = leaf_affine_attractor(out, size, 1, &raster, why, sizeof why);
    leaf_affine_raster_free(&raster);
    if (rc) snprintf(msg, msg_size, "leaf maps: %s", why);
    return rc ? -1 : TREE_LOOK_USER_MAPS;
}

int tree_look_leaf_balance(const double color[3], const double transmittance[3], char *msg, size_t msg_size)
{
    for (int k = 0; k < 3; k++)
        if (color[k] + transmittance[k] > 1.0) {
            snprintf(msg, msg_size, "leaf_color + leaf_transmittance is %g in channel %d; a leaf cannot scatter more "
                     "light than it receives, so keep the sum at most 1", color[k] + transmittance[k], k);
            return -1;
        }
    return 0;
}

int tree_look_bark(int preset, double angle_deg, bark_fractal_params *out, char *msg, size_t msg_size)
{
    if (preset < 0 || preset >= BARK_FRACTAL_PRESETS) {
        snprintf(msg, msg_size, "bark %d is not a preset; give smooth, scaly, furrowed or fissured", preset);
        return -1;
    }
    *out = bark_fractal_preset_params((bark_fractal_preset)preset);
    if (isfinite(angle_deg)) out->theta = angle_deg * (M_PI / 180.0);
    return bark_fractal_check(out, msg, msg_size);
}

void tree_look_bark_texture(const bark_fractal_params *p, uint32_t size, uint8_t *rgba)
{
    float height[TREE_LOOK_MAX_BARK_SIZE]; /* one row at a time, at texel centres */
    if (size > TREE_LOOK_MAX_BARK_SIZE) size = TREE_LOOK_MAX_BARK_SIZE;
    for (uint32_t row = 0; row < size; row++) {
        double v = 1.0 - (row + 0.5) / size;
        for (uint32_t x = 0; x < size; x++) height[x] = (float)bark_fractal_height(p, (x + 0.5) / size, v);
        bark_fractal_albedo(p, size, 1, height, rgba + (size_t)row * size * 4);
    }
}
