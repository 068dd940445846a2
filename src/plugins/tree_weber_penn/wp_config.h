/* wp_config.h — a tree_weber_penn block read into what the plugin grows and draws: the species
 * (from `file` and `name`, each `model` key replacing the file's value, or from `model` alone
 * over Arbaro's defaults), the seed, the leaf (the species' own shape or an affine-map texture on
 * a card) and the colours and bark.
 *
 * wp_config_read() checks what the schema cannot: one of file and model given, the species
 * named when the file holds several (an unknown name refused with the names it has), whole
 * numbers in the per-level integer lists, every per-level value in wp_param_table's range at
 * the levels the tree grows (wp_param_used), the leaf's maps, the bark and the leaf's energy
 * balance. Each failure names the key at fault (file, name, model.<member>, leaf, ...) and its
 * place.
 *
 * Ownership: a wp_config owns nothing; it is a plain value. */
#ifndef WP_CONFIG_H
#define WP_CONFIG_H

#include <stdint.h>

#include "bark_fractal.h"
#include "leaf_affine.h"
#include "plugin_err.h"
#include "plugin_params.h"
#include "wp_params.h"

#define WP_LEAF_TEXTURE_SIZE 128u /* square, the leaf's unit square */
#define WP_LEAF_TEXTURE_SEED 1u   /* the chaos game's seed: every scene, the same leaves */
#define WP_BARK_TEXTURE_SIZE 128u /* square, one circumference wide and long */

typedef enum wp_leaf_kind {
    WP_LEAF_OWN = 0, /* the species' LeafShape mesh (wp_leaf_shape.h) */
    WP_LEAF_CARD = 1 /* a card with the leaf's area and the affine-map texture (wp_leaf_form.h) */
} wp_leaf_kind;

typedef struct wp_config {
    wp_params species;        /* the full-grown tree's parameters */
    int64_t seed;             /* Arbaro's seed of the full-grown variant */
    const sylva_params *where; /* the plugin's block, borrowed */
    const char *where_key;    /* "model" when given, else "file": the key a failure of the species is reported at */
    const sylva_params *model; /* the `model` group when the scene gives it, else NULL; borrowed */
    wp_leaf_kind leaf;
    leaf_affine_maps leaf_maps; /* WP_LEAF_CARD: the texture's maps */
    double leaf_color[3], leaf_transmittance[3], bark_color[3];
    bark_fractal_params bark;
} wp_config;

/* Reads the block of r (validated against wp_schema) into *cfg. Returns SYLVA_OK; r's status when
 * the code read a name the schema lacks (the host has the sentence); or a negative status with
 * err saying what is wrong and what would be valid, at its key. */
int wp_config_read(plugin_params *r, wp_config *cfg, plugin_err *err);

#endif
