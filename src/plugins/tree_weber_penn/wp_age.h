/* wp_age.h — a Weber–Penn species at a normalised age in (0, 1]. The paper and Arbaro grow only
 * the full-grown tree; the plugin makes a younger one from the model's own stages
 * (docs/models/tree_weber_penn.md, "Ages"): Scale and ScaleV (so every stem length and radius,
 * which the model takes relative to Scale) times the age, and the first ceil(age Levels) stem
 * levels (at least 2), the last level grown bearing the leaves placed as the species places
 * them. Age 1 is the species unchanged. */
#ifndef WP_AGE_H
#define WP_AGE_H

#include <stdint.h>

#include "wp_params.h"

/* The stem levels grown at `age` by a species of `levels`: ceil(age levels), at least 2 (Arbaro
 * grows no leaves on the trunk, so a tree of one level would be a bare pole), at most levels. */
int wp_age_levels(int levels, double age);

/* *out = *full at `age` in (0, 1] (age >= 1: *full itself). */
void wp_params_at_age(const wp_params *full, double age, wp_params *out);

/* Arbaro's seed of variant `variant` of n_variants (the host's order: youngest first, the
 * full-grown last) for a species of seed `seed`: the full-grown variant takes `seed` itself, each
 * younger one the next seed up (seed + n_variants - 1 - variant). */
int64_t wp_variant_seed(int64_t seed, uint32_t variant, uint32_t n_variants);

#endif
