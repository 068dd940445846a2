/* eco_lifecycle.c — growing every plant a year (4.32; dominated plants do not grow, as the
 * thesis's model and Fig. C.11 do), its radius (4.33), power (4.18) and the species' seeds
 * (4.31); and removing the dead: at the death age (4.26), a dominated plant with chance p_m,
 * and — sylva's rule, which the thesis leaves unprinted — a plant in unfavourable conditions
 * with chance env_death (1 - c) for each factor whose favourability c is below 1, each factor
 * drawing from its own stream in the order altitude, humidity, sunniness, windiness, slope. Each
 * species has its own plants and streams, so the species run on worker threads with the same
 * result for any thread count. */
#include "eco_growth.h"
#include "plugin_threads.h"
#include "eco_sim.h"

/* One species' year of growth: it writes only its own plants and seeds. */
static void grow_species(void *ctx, uint32_t worker, uint64_t j)
{
    (void)worker;
    eco_sim *s = ctx;
    const eco_species *sp = &s->species[j];
    eco_population *pop = &s->pop[j];
    double seeds = 0;
    for (uint32_t q = 0; q < pop->n; q++) {
        eco_plant *pl = &pop->plants[q];
        if (!pl->dominated) {
            pl->h += eco_growth(sp, pl->age, pl->v);
            if (pl->h > 1) pl->h = 1;
        }
        pl->age++;
        pl->r = pl->h * sp->r_s;
        pl->power = eco_power(pl->v, pl->h, s->p_r[j]);
        if (pl->age >= sp->t_m) seeds += pl->power;
    }
    s->seeds[j] = seeds;
}

void eco_grow(eco_sim *s) { plugin_threads_run(s->config.threads, s->n_species, grow_species, s, NULL, NULL); }

typedef struct death_job {
    eco_sim *s;
    const eco_random *rnd;
} death_job;

/* One species' deaths: its own plants and its own streams, so the species run on any thread. */
static void remove_dead_species(void *ctx, uint32_t worker, uint64_t j)
{
    (void)worker;
    static const struct {
        int fav;
        eco_stream stream;
    } env[5] = {{ECO_FAV_ALTITUDE, ECO_RNG_DEATH_ALTITUDE},
                {ECO_FAV_HUMIDITY, ECO_RNG_DEATH_HUMIDITY},
                {ECO_FAV_SUNNINESS, ECO_RNG_DEATH_SUNNINESS},
                {ECO_FAV_WINDINESS, ECO_RNG_DEATH_WINDINESS},
                {ECO_FAV_SLOPE, ECO_RNG_DEATH_SLOPE}};
    const death_job *job = ctx;
    eco_sim *s = job->s;
    const eco_random *rnd = job->rnd;
    const eco_species *sp = &s->species[j];
    eco_population *pop = &s->pop[j];
    sylva_rng *rng = &s->rng[j * ECO_N_STREAMS];
    uint32_t kept = 0;
    for (uint32_t q = 0; q < pop->n; q++) {
        const eco_plant *pl = &pop->plants[q];
        int dead = pl->age >= pl->t_max;
        if (!dead && pl->dominated) dead = rnd->uniform(&rng[ECO_RNG_DEATH_DOMINANCE]) < sp->p_m;
        for (int f = 0; f < 5 && !dead && sp->env_death > 0; f++) {
            double c = pl->fav[env[f].fav];
            if (c < 1) dead = rnd->uniform(&rng[env[f].stream]) < sp->env_death * (1.0 - c);
        }
        if (!dead) pop->plants[kept++] = *pl;
    }
    pop->n = kept;
}

void eco_remove_dead(eco_sim *s, const eco_random *rnd)
{
    death_job job = {s, rnd};
    plugin_threads_run(s->config.threads, s->n_species, remove_dead_species, &job, NULL, NULL);
}
