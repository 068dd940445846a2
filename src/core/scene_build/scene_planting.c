/* scene_planting.c — a planting plan felled, planted and grown to a year (scene_planting.h). */
#include "scene_build/scene_planting.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "scene_build/planting_ecology.h"
#include "scene_build/planting_growth.h"
#include "scene_build/planting_layout.h"
#include "scene_build/planting_stock.h"
#include "scene_build/scene_trees.h"
#include "site/terrain_extent.h"

/* More plants than this in one plan is a spacing given in the wrong unit. */
#define PLANTING_MAX_PLANTS 20000000u

static const char *const kind_nouns[PLANTING_KINDS] = {"block", "belt", "tree", "felling"};

/* Every point of every feature on the terrain; refused at the first that is not. */
static int plan_on_terrain(const scene *s, const scene_file *sf, err_buf *err)
{
    const planting_spec *plan = &sf->planting;
    for (uint32_t fi = 0; fi < plan->n_features && s->terrain; fi++) {
        const planting_feature *f = &plan->features[fi];
        for (uint32_t k = 0; k < f->n_xy; k++) {
            double z;
            if (!scene_terrain_height(s, f->xy[k][0], f->xy[k][1], &z)) continue;
            char where[512];
            terrain_extent_text(s, f->xy[k][0], f->xy[k][1], where, sizeof where);
            return err_at(err, ERR_INPUT, f->file, f->line, f->column,
                          "planting: the %s '%s' lies outside the terrain: its point %u at local (%.1f, %.1f) is "
                          "outside the terrain%s; draw the plan on the site, in the site's coordinates",
                          kind_nouns[f->kind], f->name, k, f->xy[k][0], f->xy[k][1], where);
        }
    }
    return 0;
}

/* Takes out the plants standing inside a felling's polygon (all of them: the scene's existing
 * vegetation is placed before the plan). Returns how many. */
static uint32_t fell(scene *s, const planting_spec *plan)
{
    uint32_t kept = 0, n = s->n_instances;
    for (uint32_t i = 0; i < n; i++) {
        const instance *in = &s->instances[i];
        double x = in->xf.m[0][3], y = in->xf.m[1][3];
        int felled = 0;
        for (uint32_t fi = 0; fi < plan->n_features && !felled; fi++) {
            const planting_feature *f = &plan->features[fi];
            felled = f->kind == PLANTING_FELLING &&
                     planting_ring_contains((const double (*)[2])f->xy, f->n_xy, x, y);
        }
        if (!felled) s->instances[kept++] = *in;
    }
    s->n_instances = kept;
    return n - kept;
}

typedef struct planting_tally {
    uint32_t placed, thinned, died, outside;
    double lowest, tallest;
} planting_tally;

/* A young plant: young prototype proto standing at t's place, scaled to t's height. Returns as
 * scene_place_sized_tree does. */
static int place_young(scene *s, uint32_t proto, const tree_spec *t, err_buf *err)
{
    double z = 0;
    if (s->terrain && scene_terrain_height(s, t->position[0], t->position[1], &z)) return 1;
    double p[3] = {t->position[0], t->position[1], z};
    xform3x4 xf = plant_transform(p, t->rotation_deg, t->height / s->prototypes[proto].height);
    return scene_add_instance(s, proto, &xf, err) < 0 ? -1 : 0;
}

/* Plant p (number id in the plan) at its age after `years`: young, or its species' model; none
 * when thinned, or when the ecology's history (died: the year it died in, 0 none) has it dead. */
static int plant_one(scene *s, const scene_file *sf, const planted_plant *p, uint32_t id, double years,
                     uint32_t died, const planting_young *young, planting_tally *tally, err_buf *err)
{
    const planting_spec *plan = &sf->planting;
    const planting_feature *f = &plan->features[p->feature];
    if (f->kind != PLANTING_TREE && plan->thinning_year > 0 && years >= plan->thinning_year &&
        p->thinning_rank >= plan->thinning_keep) {
        tally->thinned++;
        return 0;
    }
    if (died) {
        tally->died++;
        return 0;
    }
    double age0 = planting_age_for_height(s, p->species, plan->full_grown_age, p->stock_height);
    if (age0 < 0)
        return err_at(err, ERR_INPUT, f->file, f->line, f->column, "planting: the %s '%s': its stock of %.2f m is "
                      "taller than species '%s' grows (its full-grown model is %.2f m); give a smaller stock or "
                      "another species", kind_nouns[f->kind], f->name, p->stock_height, s->species[p->species].name,
                      planting_tallest(s, p->species));
    double age = age0 + years;
    tree_spec t = {.species = p->species, .position = {p->xy[0], p->xy[1]},
                   .height = planting_height_at(s, p->species, plan->full_grown_age, age),
                   .age = fmax(1e-9, fmin(1.0, age / plan->full_grown_age)), .rotation_deg = p->rotation_deg,
                   .feature = f->name};
    int64_t proto = planting_young_prototype(young, p, id);
    int rc = proto >= 0 ? place_young(s, (uint32_t)proto, &t, err) : scene_place_sized_tree(s, &t, 0, err);
    if (rc < 0) return err_prefix(err, "planting: ");
    if (rc == 1) {
        tally->outside++;
        return 0;
    }
    s->instances[s->n_instances - 1].planted = id + 1;
    tally->placed++;
    tally->lowest = fmin(tally->lowest, t.height), tally->tallest = fmax(tally->tallest, t.height);
    return 0;
}

int scene_build_planting(scene *s, const scene_file *sf, const plugin_registry *reg, ecology_session *ecology,
                         const build_options *opt, err_buf *err)
{
    const planting_spec *plan = &sf->planting;
    if (!plan->n_features && opt->planting_shown)
        return err_at(err, ERR_INPUT, sf->path, 1, 1, "--year %g shows a planting plan N years after planting, and "
                      "the scene has no 'planting:' section", opt->planting_years);
    if (!plan->n_features) return 0;
    if (plan_on_terrain(s, sf, err)) return -1;
    if (!opt->planting_shown) {
        if (!opt->quiet)
            fprintf(stderr, "planting: the plan of %.0f is not shown: the scene as it stands before it (--year N "
                    "shows it N years after planting)\n", plan->year);
        return 0;
    }
    s->planting_shown = 1, s->planting_years = opt->planting_years, s->planting_year = plan->year;
    uint32_t felled = fell(s, plan), n = 0;
    planted_plant *plants = planting_layout_new(plan, PLANTING_MAX_PLANTS, &n, err); /* owned here */
    if (!plants) return err_prefix(err, "planting: ");
    planting_tally tally = {.lowest = INFINITY, .tallest = 0};
    uint32_t *died = NULL; /* owned here: each plant's year of death by the ecology, or NULL */
    const char *no_ecology = NULL;
    if (planting_ecology_fates(s, sf, reg, ecology, opt, plants, n, opt->planting_years, &died, &no_ecology, err)) {
        free(plants);
        return -1;
    }
    planting_young young; /* its arrays owned here */
    int rc = planting_young_build(s, plan, plants, n, opt->planting_years, &young, err);
    for (uint32_t i = 0; i < n && !rc; i++)
        rc = plant_one(s, sf, &plants[i], i, opt->planting_years, died ? died[i] : 0, &young, &tally, err);
    planting_young_release(&young);
    free(plants), free(died);
    if (rc) return -1;
    if (!opt->quiet) {
        fprintf(stderr, "planting: year %g after planting (%.0f): %u plants", opt->planting_years,
                plan->year + floor(opt->planting_years), tally.placed);
        if (tally.placed) fprintf(stderr, ", %.2f-%.2f m tall", tally.lowest, tally.tallest);
        if (tally.placed && opt->planting_years < PLANTING_ESTABLISHMENT_YEARS)
            fprintf(stderr, ", young (as the nursery stock grows, until year %g)", PLANTING_ESTABLISHMENT_YEARS);
        if (tally.thinned) fprintf(stderr, ", %u thinned", tally.thinned);
        if (no_ecology) fprintf(stderr, ", none lost to competition or death (%s)", no_ecology);
        else fprintf(stderr, ", %u lost to competition or death by the ecology", tally.died);
        if (tally.outside) fprintf(stderr, ", %u past the terrain's edge left out", tally.outside);
        fprintf(stderr, "; %u existing plants felled\n", felled);
    }
    return 0;
}
