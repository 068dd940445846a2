/* planting_stock.h — a planting plan's plants in their first years drawn as the nursery stock
 * they were planted as, growing into their species' model (docs/mitigation.md, "How a young
 * plant looks").
 *
 * Until PLANTING_ESTABLISHMENT_YEARS after planting a planted plant is not its species' model
 * scaled down but a young plant of its stock's form (stock_mesh.h): a whip's single stem, a
 * feathered tree's leader with side shoots down most of its height, a standard's clear stem under
 * a few crown branches, each with the species' own leaf, sparse, and the guard or stake it was
 * planted with for its first PLANTING_GUARD_YEARS. Over the establishment years its crown's
 * reach and its leaves grow linearly from the stock's to those of the species' model at the
 * plant's age and height (the variant the plant is drawn as afterwards, scaled as it will be), so
 * the belt thickens year by year and meets the model at the end of the period without a jump in
 * width or leafage. Its height is the growth curve's (planting_growth.h), to the leader's tip.
 *
 * The young plants of a plan are prototypes of a species of their own beside the model's (the
 * same name; species.young_stock_of names the model's), built before any plant is placed so that
 * its prototypes are contiguous: PLANTING_STOCK_INDIVIDUALS individuals per species, stock form
 * and stock size, each plant drawn as one of them chosen by its number in the plan and scaled to
 * its own height. Everything comes from the plan's seed: the same plants every build.
 *
 * Ownership: planting_young_build fills a planting_young whose arrays the caller frees with
 * planting_young_release; the prototypes and species it adds are the scene's. */
#ifndef SYLVA_PLANTING_STOCK_H
#define SYLVA_PLANTING_STOCK_H

#include <stdint.h>

#include "scene/scene.h"
#include "scene_build/planting_layout.h"
#include "scene_file/scene_file_spec.h"

#define PLANTING_ESTABLISHMENT_YEARS 8.0 /* a belt at 1.5 m closes its canopy in 8 to 10 years */
#define PLANTING_GUARD_YEARS 5.0         /* guards and stakes come off after five seasons */
#define PLANTING_STOCK_INDIVIDUALS 6u

/* The young prototypes of one plan at one year. */
typedef struct planting_young {
    uint32_t *first;        /* per feature and place in its species list (fi PLANTING_MAX_SPECIES +
                               k): the first of its young prototypes, UINT32_MAX for none; owned */
    uint32_t *count;        /* likewise: how many (the individuals); owned */
    uint32_t *species;      /* likewise: the model species they draw; owned */
    uint32_t n_features;
} planting_young;

/* Builds, when `years` is below PLANTING_ESTABLISHMENT_YEARS, the young prototypes of every
 * species and stock of the n plants of plan (plants as planting_layout_new lays them out).
 * Returns 0, or -1 with err set. */
int planting_young_build(scene *s, const planting_spec *plan, const planted_plant *plants, uint32_t n, double years,
                         planting_young *y, err_buf *err);

/* The prototype plant p (number id in the plan) is drawn as, or -1 when it is drawn as its
 * species' model. */
int64_t planting_young_prototype(const planting_young *y, const planted_plant *p, uint32_t id);

void planting_young_release(planting_young *y); /* accepts an empty one */

#endif
