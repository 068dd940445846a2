/* tree_look.h — the keys every tree plugin reads for its leaf and bark textures: `leaf:` (a
 * leaf_affine preset name or user maps in leaf_affine_parse's text form) and `bark:` (a
 * bark_fractal preset name) with `bark_angle:` (the angle theta of lambda = e^{i theta}, in
 * degrees; absent: the preset's). The schema entries are the plugins' own; this file turns the
 * values into leaf maps and bark parameters, with one sentence on what is wrong. */
#ifndef TREE_LOOK_H
#define TREE_LOOK_H

#include <stddef.h>
#include <stdint.h>

#include "bark_fractal.h"
#include "leaf_affine.h"

/* The bark presets' names in bark_fractal_preset order, NULL-terminated (an enum's choices). */
extern const char *const tree_look_bark_names[BARK_FRACTAL_PRESETS + 1];

#define TREE_LOOK_USER_MAPS LEAF_AFFINE_PRESET_COUNT /* tree_look_leaf's answer for maps */

/* The leaf of `text`: a preset's name (beech, maple, spruce, shrub, willow) or user maps, whose
 * attractor must lie in the unit square on a size x size texture (the chaos game is run once to
 * see). Returns the leaf_affine_preset named, TREE_LOOK_USER_MAPS for maps, or -1 with "what is
 * wrong, what would be valid" in msg (out of memory included). */
int tree_look_leaf(const char *text, uint32_t size, leaf_affine_maps *out, char *msg, size_t msg_size);

/* The bark of preset `preset` with theta = angle_deg degrees (the preset's when angle_deg is
 * not finite). Returns 0, or -1 with a sentence in msg. */
int tree_look_bark(int preset, double angle_deg, bark_fractal_params *out, char *msg, size_t msg_size);

/* Whether a leaf of albedo `color` and transmittance `transmittance` (the `leaf_color:` and
 * `leaf_transmittance:` keys, linear RGB) scatters at most what it receives: 0, or -1 with a
 * sentence naming the channel in msg. */
int tree_look_leaf_balance(const double color[3], const double transmittance[3], char *msg, size_t msg_size);

#define TREE_LOOK_MAX_BARK_SIZE 1024u

/* Fills rgba (size * size * 4 bytes, sRGB-encoded, row 0 at the top; size at most
 * TREE_LOOK_MAX_BARK_SIZE) with the albedo of bark p: one circumference wide and long, so it
 * tiles round and along a branch. */
void tree_look_bark_texture(const bark_fractal_params *p, uint32_t size, uint8_t *rgba);

#endif
