/* scene_trees.c — surveyed trees placed as plants scaled to their measured size
 * (scene_trees.h). */
#include "scene_build/scene_trees.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "scene_build/plant_scale.h"
#include "site/terrain_extent.h"

/* Above this factor over a species' full-grown model a tree is named in a warning. */
#define TREES_STRETCH_WARN 1.5

typedef struct trees_tally {
    uint32_t outside, stretched;
    const tree_spec *first_outside, *most_stretched;
    double largest_factor;
} trees_tally;

/* How much taller than its species' full-grown model the tree is, counted when notable. */
static void tally_stretch(const scene *s, const tree_spec *t, trees_tally *tally)
{
    const species *p = &s->species[t->species];
    double factor = t->height / s->prototypes[p->first_prototype + p->n_variants - 1].height;
    if (!(factor > TREES_STRETCH_WARN)) return;
    tally->stretched++;
    if (factor > tally->largest_factor) tally->largest_factor = factor, tally->most_stretched = t;
}

int scene_place_sized_tree(scene *s, const tree_spec *t, int development, err_buf *err)
{
    double z = 0;
    if (s->terrain && scene_terrain_height(s, t->position[0], t->position[1], &z)) return 1;
    const species *p = &s->species[t->species];
    if (!p->n_variants) return err_set(err, "%s: species '%s' has no model", t->feature, p->name);
    uint32_t v = t->age > 0 ? scene_variant_for_age(s, t->species, t->age) : scene_variant_nearest_height(s, t->species, t->height);
    uint32_t proto = p->first_prototype + v;
    const prototype *pr = &s->prototypes[proto];
    if (!(pr->height > 0))
        return err_set(err, "%s: the model of species '%s' (variant %u) has no height to scale to the tree's %g m",
                       t->feature, p->name, v, t->height);
    double sv, sh;
    plant_scales(pr, t->height, t->crown, &sv, &sh);
    xform3x4 xf = xf_trs(v3((float)t->position[0], (float)t->position[1], (float)z), v3(0, 0, (float)t->rotation_deg),
                         v3((float)sh, (float)sh, (float)sv));
    if (scene_add_instance(s, proto, &xf, err) < 0) return -1;
    s->instances[s->n_instances - 1].development = development;
    return 0;
}

/* One tree as an instance; 0 also when it stands outside the terrain (left out, counted). */
static int place_tree(scene *s, const tree_spec *t, int development, trees_tally *tally, err_buf *err)
{
    int rc = scene_place_sized_tree(s, t, development, err);
    if (rc == 1 && !tally->outside++) tally->first_outside = t;
    if (!rc) tally_stretch(s, t, tally);
    return rc < 0 ? -1 : 0;
}

static void warn(const scene *s, const scene_file *sf, const trees_tally *tally)
{
    const trees_spec *ts = &sf->trees;
    if (tally->outside) {
        const tree_spec *t = tally->first_outside;
        char where[512];
        terrain_extent_text(s, t->position[0], t->position[1], where, sizeof where);
        fprintf(stderr, "sylva: warning: %s:%u:%u: trees: %u of the %u trees of %s stand outside the terrain and "
                "are left out (the first: %s at local (%.1f, %.1f), outside the terrain%s)\n", sf->path, ts->line, ts->column,
                tally->outside, ts->n_trees, ts->file, t->feature, t->position[0], t->position[1], where);
    }
    if (tally->stretched) {
        const tree_spec *t = tally->most_stretched;
        fprintf(stderr, "sylva: warning: %s:%u:%u: trees: %u of the %u trees are taller than %.1f times their "
                "species' full-grown model and are scaled up, by at most %.2f (%s, %.1f m, species '%s')\n",
                sf->path, ts->line, ts->column, tally->stretched, ts->n_trees, TREES_STRETCH_WARN, tally->largest_factor, t->feature,
                t->height, s->species[t->species].name);
    }
}

int scene_build_trees(scene *s, const scene_file *sf, const build_options *opt, err_buf *err)
{
    (void)opt; /* warnings print even when quiet */
    const trees_spec *ts = &sf->trees;
    trees_tally tally = {0};
    for (uint32_t i = 0; i < ts->n_trees; i++)
        if (place_tree(s, &ts->trees[i], ts->development, &tally, err)) {
            err_buf why = *err;
            return err_at(err, why.status ? why.status : ERR_INPUT, sf->path, ts->line, ts->column, "trees: '%s' %s",
                          ts->file, err_sentence(&why));
        }
    if (ts->n_trees && tally.outside == ts->n_trees) {
        const tree_spec *t = tally.first_outside;
        char where[512];
        terrain_extent_text(s, t->position[0], t->position[1], where, sizeof where);
        return err_at(err, ERR_INPUT, sf->path, ts->line, ts->column,
                      "trees: none of the %u trees of %s stands on the terrain (the first, %s, is at local "
                      "(%.1f, %.1f), outside the terrain%s); is the survey of this site, and its CRS the one it states?", ts->n_trees,
                      ts->file, t->feature, t->position[0], t->position[1], where);
    }
    warn(s, sf, &tally);
    return 0;
}
