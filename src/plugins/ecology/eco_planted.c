/* eco_planted.c — the fate of plants set out by hand (a planting plan's blocks and belts): grown
 * year by year among themselves by the run's own rules, so that the ecology decides which of
 * them stand. Each year is Algorithm 9 without its first step: grow (4.32; radius 4.33, power
 * 4.18, dominated plants do not grow), find dominance (Algorithm 8), remove the dead (the death
 * age 4.26, a dominated plant with chance p_m, unfavourable conditions with chance
 * env_death (1 - c)) — eco_grow, eco_find_dominance and eco_remove_dead themselves, run on a
 * cohort that borrows the run's terrain, species and N_opt (4.27) and owns its plants, streams
 * and search grid. No seedlings are added: a planting plan's ground is managed. A plant is
 * dominated by none in its first year in the ground (first_year_free); one that dies in a year up
 * to its replaced_until (the plan's establishment period) is replaced in kind: the same stock set
 * out again in its place, under its number, so it is not counted dead.
 *
 * A planted plant's normalised height at planting is its stock's height over its species'
 * model height; its age the age at planting, rounded to whole years as the run counts them;
 * its vigour (4.20) from the favourabilities of its patch (4.21–4.25); its death age drawn as
 * a seedling's (4.26). The growth area, the edge band and the habitat say where seedlings take
 * root and do not apply: a plant is planted where the plan draws it.
 *
 * Randomness: the cohort's streams are the run's purposes, each keyed by the cohort's seed and
 * the species' name ("planted:NAME:PURPOSE"), never the run's streams; each species draws from
 * its own in plant order, so the deaths are the same for any thread count, and a year's draws
 * depend only on the years before it: fewer years give the same deaths up to their last.
 *
 * Ownership: everything allocated here is freed before returning; the run is only read. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eco_growth.h"
#include "eco_sim.h"

/* The cohort's own parts, freed here; every other pointer of the struct is the run's. */
static void cohort_release(eco_sim *c)
{
    for (uint32_t j = 0; c->pop && j < c->n_species; j++) free(c->pop[j].plants);
    free(c->pop), free(c->seeds), free(c->rng);
    free(c->cell_start), free(c->patch_r_max), free(c->cell);
}

/* The run's species index of request species `species`, or n_species when the run lacks it. */
static uint32_t run_species(const eco_sim *run, uint32_t species)
{
    for (uint32_t j = 0; j < run->n_species; j++)
        if (run->request_index[j] == species) return j;
    return run->n_species;
}

/* Counts each species' plants, allocates the populations, streams and search scratch. */
static int cohort_start(eco_sim *c, const eco_sim *run, const eco_random *rnd, const sylva_ecology_planted *plants,
                        uint32_t n, uint64_t seed, plugin_err *err)
{
    *c = *run;
    c->pop = NULL, c->seeds = NULL, c->rng = NULL, c->carry = NULL;
    c->cell_start = NULL, c->patch_r_max = NULL, c->cell = NULL, c->cell_cap = 0;
    c->year = 0;
    uint32_t ns = run->n_species ? run->n_species : 1;
    c->pop = calloc(ns, sizeof *c->pop);
    c->seeds = calloc(ns, sizeof *c->seeds);
    c->rng = calloc((size_t)ns * ECO_N_STREAMS, sizeof *c->rng);
    if (!c->pop || !c->seeds || !c->rng) return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for planted plants");
    for (uint32_t i = 0; i < n; i++) {
        uint32_t j = run_species(run, plants[i].species);
        if (j < run->n_species) c->pop[j].cap++;
    }
    for (uint32_t j = 0; j < run->n_species; j++) {
        if (!(c->pop[j].plants = malloc((c->pop[j].cap ? c->pop[j].cap : 1) * sizeof *c->pop[j].plants)))
            return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for %u planted plants", c->pop[j].cap);
        for (int p = 0; p < ECO_N_STREAMS; p++) {
            char purpose[160];
            snprintf(purpose, sizeof purpose, "planted:%s:%s", run->names[j], eco_stream_purposes[p]);
            rnd->stream(rnd->ctx, &c->rng[(size_t)j * ECO_N_STREAMS + p], purpose, seed);
        }
    }
    return SYLVA_OK;
}

/* Plant i set out on its patch in `year` as a seedling is (eco_reproduce.c's sow), at its stock's
 * height and age. A plant off the terrain's grid takes no part. */
static void set_out(eco_sim *c, const eco_random *rnd, const sylva_ecology_planted *pp, uint32_t i, uint32_t year)
{
    uint32_t j = run_species(c, pp->species);
    const eco_terrain *t = &c->terrain;
    int64_t p = eco_patch_of(t, pp->position[0], pp->position[1]);
    if (j >= c->n_species || p < 0) return;
    const eco_species *sp = &c->species[j];
    double h = pp->height / c->model_height[j];
    eco_plant *pl = &c->pop[j].plants[c->pop[j].n++];
    *pl = (eco_plant){.x = pp->position[0], .y = pp->position[1], .z = eco_height_at(t, pp->position[0], pp->position[1]),
                      .h = h > 1 ? 1 : h > 0 ? h : 0, .patch = (uint32_t)p, .planted = i, .set_out_in = year,
                      .age = pp->age > 0 ? (uint32_t)floor(pp->age + 0.5) : 0};
    eco_plant_settle(c, j, pl, rnd);
    pl->r = pl->h * sp->r_s;                         /* (4.33) */
    pl->power = eco_power(pl->v, pl->h, c->p_r[j]); /* (4.18) */
}

/* A plant in its first year in the ground is dominated by none (docs/models/ecology.md, "Planted
 * plants": Algorithm 8 waits a year): the plants of a planting are set out together, of one
 * nursery grade, their roots still in their pits, and a few centimetres of the grade's spread
 * make none the master of its neighbour. Their ecological circles (4.33) overlap from the start
 * when they are planted closer than 2 h R_s, so without this the shorter of each pair would be
 * dominated (and may die, p_m) from the first year. From the second year Algorithm 8 acts. */
static void first_year_free(eco_sim *c, uint32_t year)
{
    for (uint32_t j = 0; j < c->n_species; j++)
        for (uint32_t q = 0; q < c->pop[j].n; q++)
            if (c->pop[j].plants[q].set_out_in + 1 == year) c->pop[j].plants[q].dominated = 0;
}

/* Takes out the plants whose taken_out year is `year` (management: thinning), keeping order. */
static void take_out(eco_sim *c, const sylva_ecology_planted *plants, uint32_t year)
{
    for (uint32_t j = 0; j < c->n_species; j++) {
        uint32_t kept = 0;
        for (uint32_t q = 0; q < c->pop[j].n; q++) {
            const eco_plant *pl = &c->pop[j].plants[q];
            if (plants[pl->planted].taken_out != year) c->pop[j].plants[kept++] = *pl;
        }
        c->pop[j].n = kept;
    }
}

int eco_planted_fate(const eco_sim *run, const eco_random *rnd, const sylva_ecology_planted *plants, uint32_t n,
                     uint32_t years, uint64_t seed, uint32_t *died, plugin_err *err)
{
    for (uint32_t i = 0; i < n; i++) died[i] = 0;
    if (!n) return SYLVA_OK;
    uint8_t *standing = calloc(n, 1); /* owned here: per plant, whether it stood before a year's deaths */
    if (!standing) return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for %u planted plants", n);
    eco_sim c; /* the cohort: its own parts freed by cohort_release, the rest the run's */
    int rc = cohort_start(&c, run, rnd, plants, n, seed, err);
    for (uint32_t i = 0; i < n && !rc; i++) {
        if (!(plants[i].height > 0) || !isfinite(plants[i].position[0]) || !isfinite(plants[i].position[1]))
            rc = plugin_fail(err, SYLVA_ERR_PARAM, "planted plant %u has no height or no position", i);
        else set_out(&c, rnd, &plants[i], i, 0);
    }
    for (uint32_t y = 1; y <= years && !rc; y++) {
        take_out(&c, plants, y);
        for (uint32_t j = 0; j < c.n_species; j++)
            for (uint32_t q = 0; q < c.pop[j].n; q++) standing[c.pop[j].plants[q].planted] = 1;
        eco_grow(&c);
        if ((rc = eco_find_dominance(&c, err))) break;
        first_year_free(&c, y);
        eco_remove_dead(&c, rnd);
        /* a plant standing before the year's deaths and not after them died this year */
        for (uint32_t j = 0; j < c.n_species; j++)
            for (uint32_t q = 0; q < c.pop[j].n; q++) standing[c.pop[j].plants[q].planted] = 2;
        /* one that died within the establishment period is replaced in kind, in plan order */
        for (uint32_t i = 0; i < n; i++) {
            if (standing[i] == 1 && y <= plants[i].replaced_until) set_out(&c, rnd, &plants[i], i, y);
            else if (standing[i] == 1) died[i] = y;
            standing[i] = 0;
        }
    }
    cohort_release(&c);
    free(standing);
    return rc;
}
