/* eco_run.c — the "sylva.ecology.v1" interface of the `ecology` plugin: a run the host steps
 * year by year, reads plants and factor maps from, and saves and loads; and the two pieces
 * generate() shares with it (starting a run, simulating years with progress). */
#include <stdlib.h>

#include "eco_plugin.h"

struct sylva_ecology_run {
    eco_sim *sim;          /* owned */
    uint32_t years_wanted; /* the scene's `years` */
};

int eco_run_start(const eco_plugin_state *st, const sylva_host_api *api, sylva_host *host,
                  const sylva_ecology_request *req, eco_sim **out)
{
    return eco_sim_new(api, host, &st->located, &st->cfg, st->only, req, out);
}

int eco_run_years(eco_sim *sim, const sylva_host_api *api, sylva_host *host, uint32_t years)
{
    for (uint32_t y = 0; y < years; y++) {
        int rc = eco_sim_step(sim, api, host);
        if (rc) return rc;
        api->progress(host, "ecology", y + 1, years);
    }
    return SYLVA_OK;
}

static int run_new(void *state, const sylva_host_api *api, sylva_host *host, const sylva_ecology_request *req,
                   sylva_ecology_run **run)
{
    *run = NULL;
    const eco_plugin_state *st = state;
    if (!st || !req || req->size < sizeof *req) return api->error(host, "run_new needs the plugin's state and a request");
    sylva_ecology_run *r = calloc(1, sizeof *r);
    if (!r) return api->error(host, "out of memory");
    int rc = eco_run_start(st, api, host, req, &r->sim);
    if (rc) {
        free(r);
        return rc;
    }
    r->years_wanted = st->cfg.years;
    *run = r;
    return SYLVA_OK;
}

static void run_free(sylva_ecology_run *run)
{
    if (!run) return;
    eco_sim_free(run->sim);
    free(run);
}

static uint32_t run_years_wanted(const sylva_ecology_run *run) { return run->years_wanted; }
static uint32_t run_year(const sylva_ecology_run *run) { return run->sim->year; }

static int run_step(sylva_ecology_run *run, const sylva_host_api *api, sylva_host *host, uint32_t years)
{
    return eco_run_years(run->sim, api, host, years);
}

static uint32_t run_plant_count(const sylva_ecology_run *run, uint32_t species)
{
    const eco_sim *s = run->sim;
    if (species == SYLVA_ECOLOGY_ALL_SPECIES) return eco_sim_count(s);
    for (uint32_t j = 0; j < s->n_species; j++)
        if (s->request_index[j] == species) return s->pop[j].n;
    return 0;
}

static int run_plants(const sylva_ecology_run *run, const sylva_host_api *api, sylva_host *host, uint32_t first,
                      uint32_t count, sylva_ecology_plant_record *out)
{
    const eco_sim *s = run->sim;
    uint32_t total = eco_sim_count(s);
    if (first > total || count > total - first)
        return api->error(host, "plants %u to %u asked for; the run holds %u", first, first + count, total);
    uint32_t j = 0, q = first;
    while (j < s->n_species && q >= s->pop[j].n) q -= s->pop[j].n, j++;
    for (uint32_t c = 0; c < count; c++) {
        while (q >= s->pop[j].n) q = 0, j++;
        const eco_plant *pl = &s->pop[j].plants[q++];
        out[c] = (sylva_ecology_plant_record){.species = s->request_index[j], .position = {pl->x, pl->y, pl->z},
                                              .age = pl->age, .height = pl->h * s->model_height[j], .radius = pl->r,
                                              .vigour = pl->v};
    }
    return SYLVA_OK;
}

/* The five factors, then the water patches. */
static uint32_t run_factor_count(const sylva_ecology_run *run) { return ECO_N_FACTORS + 1; }

static int run_factor(const sylva_ecology_run *run, uint32_t index, sylva_ecology_factor_map *out)
{
    if (index > ECO_N_FACTORS) return SYLVA_ERR_PARAM;
    const eco_terrain *t = &run->sim->terrain;
    int water = index == ECO_N_FACTORS;
    *out = (sylva_ecology_factor_map){.name = water ? "water" : eco_factor_names[index], .nx = t->ni, .ny = t->nk,
                                      .x0 = t->x0, .y0 = t->y0, .dx = t->kx, .dy = t->ky,
                                      .values = water ? t->water_map : t->factor[index]};
    return SYLVA_OK;
}

static int run_save(const sylva_ecology_run *run, const sylva_host_api *api, sylva_host *host, const char *path)
{
    return eco_sim_save(run->sim, api, host, path);
}

static int run_load(sylva_ecology_run *run, const sylva_host_api *api, sylva_host *host, const char *path)
{
    return eco_sim_load(run->sim, api, host, path);
}

const sylva_ecology_ext_v1 eco_extension_v1 = {
    .size = sizeof(sylva_ecology_ext_v1),
    .run_new = run_new,
    .run_free = run_free,
    .years_wanted = run_years_wanted,
    .year = run_year,
    .step = run_step,
    .plant_count = run_plant_count,
    .plants = run_plants,
    .factor_count = run_factor_count,
    .factor = run_factor,
    .save = run_save,
    .load = run_load,
};
