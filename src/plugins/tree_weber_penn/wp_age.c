/* wp_age.c — a species at a younger age (wp_age.h). */
#include "wp_age.h"

#include <math.h>

int wp_age_levels(int levels, double age)
{
    if (levels <= 2 || age >= 1.0) return levels;
    double n = ceil(age * levels - 1e-9);
    if (!(n >= 2.0)) return 2; /* Arbaro puts no leaves on the trunk: the youngest tree has branches */
    return n > levels ? levels : (int)n;
}

/* The level whose parameters place the leaves of a tree of `levels` stem levels (Arbaro reads
 * level min(levels, 3) for the leaves). */
static int leaf_level(int levels) { return levels < WP_LEVELS - 1 ? levels : WP_LEVELS - 1; }

void wp_params_at_age(const wp_params *full, double age, wp_params *out)
{
    *out = *full;
    if (age >= 1.0) return;
    out->scale = full->scale * age;
    out->scale_v = full->scale_v * age;
    int levels = wp_age_levels(full->levels, age);
    if (levels == full->levels) return;
    out->levels = levels;
    /* The leaves now grow on level levels - 1: placed by the species' leaf level's parameters. */
    const wp_level *from = &full->level[leaf_level(full->levels)];
    wp_level *to = &out->level[leaf_level(levels)];
    to->down_angle = from->down_angle, to->down_angle_v = from->down_angle_v;
    to->rotate = from->rotate, to->rotate_v = from->rotate_v;
    to->branch_dist = from->branch_dist;
}

int64_t wp_variant_seed(int64_t seed, uint32_t variant, uint32_t n_variants)
{
    return variant < n_variants ? seed + (int64_t)(n_variants - 1 - variant) : seed;
}
