/* eco_reproduce.c — the year's new plants (004 §4.6 and §4.8): ΔN_s = 1 + g_s s_s seedlings
 * per species (4.30–4.31 with the thesis code's start of 1/g_s seeds, Fig. C.11, which is the
 * one arrival a year that colonises an empty terrain), the fraction carried to the next year;
 * each lands beside a parent with chance p_s or anywhere the plants may grow, picked through
 * Algorithm 7's sorted index list so that adding is linear in the plants. A seedling that falls
 * into water or outside the growth area is lost; one in the edge band round the area takes root
 * with the band's chance there (eco_edge.c). The seedlings from anywhere fall on the area's
 * patches as in 004; the band receives the same rain per patch besides them (from its own
 * stream, so the area's draws are the ones a hard edge makes). */
#include <math.h>
#include <stdlib.h>

#include "eco_growth.h"
#include "plugin_threads.h"
#include "eco_sim.h"

static int by_index(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return x < y ? -1 : x > y;
}

/* Patch p or one of its existing 4-neighbours, chosen uniformly (Fig. 4.18; the same patch is
 * one of the choices, as 004 §4.6 allows). */
static uint32_t beside(const eco_terrain *t, uint32_t p, double u)
{
    uint32_t i = p % t->ni, k = p / t->ni, opt[5], n = 0;
    opt[n++] = p;
    if (i > 0) opt[n++] = p - 1;
    if (i + 1 < t->ni) opt[n++] = p + 1;
    if (k > 0) opt[n++] = p - t->ni;
    if (k + 1 < t->nk) opt[n++] = p + t->ni;
    uint32_t c = (uint32_t)(u * n);
    return opt[c < n ? c : n - 1];
}

void eco_plant_settle(const eco_sim *s, uint32_t j, eco_plant *pl, const eco_random *rnd)
{
    const eco_species *sp = &s->species[j];
    float f[ECO_N_FACTORS];
    for (int q = 0; q < ECO_N_FACTORS; q++) f[q] = s->terrain.factor[q][pl->patch];
    double fav[5];
    eco_favourabilities(sp, f, fav);
    for (int q = 0; q < 5; q++) pl->fav[q] = (float)fav[q];
    pl->v = eco_vigour(fav);
    pl->t_max = eco_death_age(sp, rnd->uniform(&s->rng[(size_t)j * ECO_N_STREAMS + ECO_RNG_DEATH_AGE]));
}

/* A seedling of species j on patch p at a random point of it (Fig. 4.19); lost in water,
 * outside the growth area or the species' habitat, and in the edge band unless it takes root. The population has room
 * (reserved by the caller). */
static void sow(eco_sim *s, uint32_t j, uint32_t p, const eco_random *rnd)
{
    const eco_terrain *t = &s->terrain;
    sylva_rng *rng = &s->rng[(size_t)j * ECO_N_STREAMS];
    double x = t->x0 + (p % t->ni + rnd->uniform(&rng[ECO_RNG_POSITION_I])) * t->kx;
    double y = t->y0 + (p / t->ni + rnd->uniform(&rng[ECO_RNG_POSITION_J])) * t->ky;
    if (!s->growable[p] || (s->habitat && s->habitat[j] && !s->habitat[j][p]) || eco_in_water(t, x, y)) return;
    /* drawn only in the band, so a run without one draws what it always drew */
    if (s->establish[p] < 1.0f && !(rnd->uniform(&rng[ECO_RNG_ESTABLISH]) < s->establish[p])) return;
    eco_plant *pl = &s->pop[j].plants[s->pop[j].n++];
    *pl = (eco_plant){.x = x, .y = y, .z = eco_height_at(t, x, y), .patch = p};
    eco_plant_settle(s, j, pl, rnd);
    pl->rotation = 2.0 * M_PI * rnd->uniform(&rng[ECO_RNG_ROTATION]);
}

typedef struct sowing_job {
    eco_sim *s;
    const eco_random *rnd;
    const uint32_t *n_new;    /* per species: this year's seedlings */
    int *failed;              /* per species: 1 when its parent list could not be allocated */
} sowing_job;

/* One species' seedlings (Algorithm 7), from its own streams into its own population, whose
 * room the caller reserved: so the species may run on any thread. */
static void sow_species(void *ctx, uint32_t worker, uint64_t j)
{
    (void)worker;
    const sowing_job *job = ctx;
    eco_sim *s = job->s;
    const eco_random *rnd = job->rnd;
    const eco_species *sp = &s->species[j];
    eco_population *pop = &s->pop[j];
    uint32_t n_new = job->n_new[j];
    double band_ratio = s->n_band ? (double)s->n_band / s->n_growable : 0.0;
    uint32_t *parents = malloc((n_new ? n_new : 1) * sizeof *parents); /* owned here */
    if (!parents) {
        job->failed[j] = 1;
        return;
    }
    sylva_rng *rng = &s->rng[j * ECO_N_STREAMS];
    /* Algorithm 7: first decide every seedling (near a parent, which one; or anywhere) ... */
    uint32_t existing = pop->n, n_near = 0, n_anywhere = 0;
    for (uint32_t q = 0; q < n_new; q++) {
        if (existing && rnd->uniform(&rng[ECO_RNG_NEAR]) < sp->p_s) {
            uint32_t idx = (uint32_t)(rnd->uniform(&rng[ECO_RNG_PARENT]) * existing);
            parents[n_near++] = idx < existing ? idx : existing - 1;
        } else {
            n_anywhere++;
        }
    }
    /* ... then walk the parents once in index order ... */
    qsort(parents, n_near, sizeof *parents, by_index);
    for (uint32_t q = 0; q < n_near; q++) {
        uint32_t p = beside(&s->terrain, pop->plants[parents[q]].patch, rnd->uniform(&rng[ECO_RNG_SIDE]));
        sow(s, (uint32_t)j, p, rnd);
    }
    /* ... and place the rest anywhere the plants may grow. */
    for (uint32_t q = 0; q < n_anywhere; q++) {
        uint32_t c = (uint32_t)(rnd->uniform(&rng[ECO_RNG_ANYWHERE]) * s->n_growable);
        sow(s, (uint32_t)j, s->growable_list[c < s->n_growable ? c : s->n_growable - 1], rnd);
    }
    /* The edge band's share of that rain, at the area's density per patch (rounded at
     * random), each seedling then taking root with the band's chance where it falls. */
    if (s->n_band && n_anywhere) {
        double share = n_anywhere * band_ratio;
        uint32_t n_band = (uint32_t)(share + rnd->uniform(&rng[ECO_RNG_ESTABLISH]));
        for (uint32_t q = 0; q < n_band; q++) {
            uint32_t c = (uint32_t)(rnd->uniform(&rng[ECO_RNG_ESTABLISH]) * s->n_band);
            sow(s, (uint32_t)j, s->band_list[c < s->n_band ? c : s->n_band - 1], rnd);
        }
    }
    free(parents);
}

int eco_reproduce(eco_sim *s, const eco_random *rnd, plugin_err *err)
{
    /* How many seedlings each species brings, and room for them, in species order (the
     * max_plants check counts the species before it) ... */
    uint32_t *n_new = calloc(s->n_species ? s->n_species : 1, sizeof *n_new); /* owned here */
    int *failed = calloc(s->n_species ? s->n_species : 1, sizeof *failed);   /* owned here */
    int rc = SYLVA_OK;
    if (!n_new || !failed) {
        rc = plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for the year's seedlings");
        goto done;
    }
    uint64_t living = eco_sim_count(s);
    for (uint32_t j = 0; j < s->n_species && !rc; j++) {
        const eco_species *sp = &s->species[j];
        eco_population *pop = &s->pop[j];
        double want = 1.0 + sp->g_s * s->seeds[j] + s->carry[j]; /* (4.30) with s_s from (4.31) */
        double whole = floor(want);
        s->carry[j] = want - whole;
        if (living + whole > (double)s->config.max_plants) {
            rc = plugin_fail(err, SYLVA_ERR_LIMIT,
                             "year %u: species '%s' would bring %.0f seedlings to %llu living plants, more than "
                             "max_plants = %llu; raise max_plants or lower the species' g_s",
                             s->year + 1, s->names[j], whole, (unsigned long long)living,
                             (unsigned long long)s->config.max_plants);
            break;
        }
        n_new[j] = (uint32_t)whole;
        /* room for the band's share of the rain too: at most every seedling from anywhere times
         * band patches per area patch, plus one for the rounding */
        double band_ratio = s->n_band ? (double)s->n_band / s->n_growable : 0.0;
        uint64_t band_max = s->n_band ? (uint64_t)ceil(n_new[j] * band_ratio) + 1 : 0;
        living += n_new[j];
        if (pop->n + (uint64_t)n_new[j] + band_max > pop->cap) {
            uint64_t cap = pop->cap ? pop->cap : 64;
            while (cap < pop->n + (uint64_t)n_new[j] + band_max) cap *= 2;
            if (cap > UINT32_MAX) cap = UINT32_MAX;
            eco_plant *q = realloc(pop->plants, cap * sizeof *q);
            if (!q) {
                rc = plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for %llu plants of '%s'",
                                 (unsigned long long)cap, s->names[j]);
                break;
            }
            pop->plants = q, pop->cap = (uint32_t)cap;
        }
    }
    /* ... then every species sows its own, on worker threads. */
    if (!rc) {
        sowing_job job = {s, rnd, n_new, failed};
        plugin_threads_run(s->config.threads, s->n_species, sow_species, &job, NULL, NULL);
        for (uint32_t j = 0; j < s->n_species && !rc; j++)
            if (failed[j]) rc = plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for %u seedlings", n_new[j]);
    }
done:
    free(n_new);
    free(failed);
    return rc;
}
