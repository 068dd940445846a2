/* wp_prepare.c — Arbaro's Params.prepare and getShapeRatio (wp_prepare.h). The order of the
 * draws here is the tree's first: each level's stream is seeded from the previous one's first
 * long, and the tree's size is drawn from level 0's stream after those. */
#include "wp_prepare.h"

#include <math.h>
#include <string.h>

#include "wp_java.h"

/* The level's values as Arbaro reads them: every value below `levels`, only the leaves'
 * placement at `levels` itself, nothing past it. */
static wp_level level_as_read(const wp_params *p, int level, int levels)
{
    wp_level v;
    memset(&v, 0, sizeof v);
    if (level < levels) return p->level[level];
    if (level == levels) {
        v.branch_dist = p->level[level].branch_dist;
        v.down_angle = p->level[level].down_angle;
        v.down_angle_v = p->level[level].down_angle_v;
        v.rotate = p->level[level].rotate;
        v.rotate_v = p->level[level].rotate_v;
    }
    return v;
}

static void set_mesh_points(wp_prepared *t)
{
    const wp_params *p = t->p;
    double q = t->mesh_quality;
    static const int minimum[WP_LEVELS] = { 4, 3, 2, 1 };
    for (int i = 0; i < WP_LEVELS; i++) t->lv[i].mesh_points = minimum[i];
    if (p->lobes > 0) {
        int n = wp_java_int(p->lobes * pow(2, wp_java_int(1 + 2.5 * q)));
        int least = wp_java_int(4 * (1 + 2 * q));
        t->lv[0].mesh_points = n > least ? n : least;
    }
    for (int i = 1; i < WP_LEVELS; i++) {
        int n = wp_java_int(t->lv[i].mesh_points * (1 + 1.5 * q));
        t->lv[i].mesh_points = n > 3 ? n : 3;
    }
}

int wp_prepare(const wp_params *p, int64_t seed, wp_prepared *out, plugin_err *err)
{
    memset(out, 0, sizeof *out);
    out->p = p;
    out->levels = p->levels;
    if (p->levels > WP_LEVELS)
        return plugin_fail(err, SYLVA_ERR_PARAM,
                           "species '%s': Levels is %d; Arbaro 1.9 grows at most 4 stem levels (give Levels 0 to 4)",
                           p->species, p->levels);
    for (int l = 0; l < WP_LEVELS && l < p->levels; l++)
        if (p->level[l].seg_splits > 0 && p->level[l].split_angle == 0)
            return plugin_fail(err, SYLVA_ERR_PARAM,
                               "species '%s': %dSegSplits is %g but %dSplitAngle is 0; a level that splits needs a "
                               "split angle above 0",
                               p->species, l, p->level[l].seg_splits, l);
    int64_t chain = seed;
    for (int l = 0; l < WP_LEVELS; l++) {
        wp_level_state *lv = &out->lv[l];
        lv->level = l;
        lv->v = level_as_read(p, l, p->levels);
        wp_random_seed(&lv->random, chain);
        chain = wp_random_long(&lv->random);
        lv->saved_split_error = NAN;
    }
    wp_random_seed(&out->mesh_random, seed);
    out->mesh_quality = p->smooth;
    set_mesh_points(out);
    out->scale_tree = p->scale + wp_random_uniform(&out->lv[0].random, -p->scale_v, p->scale_v);
    return 0;
}

double wp_level_var(wp_level_state *lv, double variation)
{
    return wp_random_uniform(&lv->random, -variation, variation);
}

double wp_shape_ratio(const wp_prepared *t, double ratio, int shape)
{
    const wp_params *p = t->p;
    switch (shape) {
    case 0: return ratio;
    case 1: return 0.2 + 0.8 * sin(M_PI * ratio);
    case 2: return 0.2 + 0.8 * sin(0.5 * M_PI * ratio);
    case 3: return 1.0;
    case 4: return 0.5 + 0.5 * ratio;
    case 5: return ratio <= 0.7 ? ratio / 0.7 : (1 - ratio) / 0.3;
    case 6: return 1 - 0.8 * ratio;
    case 7: return ratio <= 0.7 ? 0.5 + 0.5 * ratio / 0.7 : 0.5 + 0.5 * (1 - ratio) / 0.3;
    case 8:
        if (ratio < 0 || ratio > 1) return 0;
        if (ratio < 1 - p->prune_width_peak) return pow(ratio / (1 - p->prune_width_peak), p->prune_power_high);
        return pow((1 - ratio) / (1 - p->prune_width_peak), p->prune_power_low);
    default: return 0;
    }
}
