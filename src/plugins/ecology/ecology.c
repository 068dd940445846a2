/* ecology.c — the `ecology` plugin: its descriptor, create() / generate() / destroy() and the
 * "sylva.ecology.v1" interface (a run the host steps year by year, reads plants and factor maps
 * from, saves and loads). This is the plugin's only file that calls the host: the model
 * (eco_sim.h and below) reports failures in a plugin_err, which plugin_report() hands to
 * api->error or api->param_error, and draws its random numbers from an eco_random made of the
 * host's streams.
 *
 * generate() simulates the scene's years and adds every living plant that has grown through
 * api->plant_add: its position, a turn about the vertical, its height in metres (the normalised
 * height times the species' model height) and its normalised age t / t_a, which picks the
 * species' age variant. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "plugin_threads.h"
#include "eco_schema.h"
#include "eco_latitude.h"
#include "eco_sim.h"
#include "plugin_host.h"
#include "plugin_params.h"
#include "sylva/plugin.h"
#include "sylva/ecology_ext.h"

/* The plugin's state between create() and destroy(): the run configuration read from the
 * scene's `ecology:` block, and where each of its keys stands in the scene file, so that a
 * problem found once the terrain is known (a growth area outside it) is still reported at its
 * key. Owns every pointer in it (copies of the scene's values). */
typedef struct eco_plugin_state {
    eco_config cfg;         /* cfg.mask points at mask */
    double *mask;           /* owned copy of growth_mask, or NULL */
    char *only;             /* owned copy of `species`, or NULL */
    char *file;             /* owned copy of the scene file's path, or NULL */
    sylva_value *where;     /* owned: per parameter, only is_set, line and column */
    sylva_params located;   /* the plugin's schema with `where`: for api->param_error */
} eco_plugin_state;

/* A run of the "sylva.ecology.v1" interface. */
struct sylva_ecology_run {
    eco_sim *sim;          /* owned */
    uint32_t years_wanted; /* the scene's `years` */
    double min_height;     /* the scene's `min_height`: shorter plants are not placed */
};

/* ---- the model's failures and random numbers, through the host ------------------------------ */

/* The model's random source: the host's keyed streams. */
static eco_random host_random(plugin_host_ref *h)
{
    return (eco_random){.stream = plugin_host_stream, .uniform = h->api->rng_uniform, .ctx = h};
}

/* Starts a run for the plugin state and request (generate() and run_new). */
static int run_start(const eco_plugin_state *st, const sylva_host_api *api, sylva_host *host,
                     const sylva_ecology_request *req, eco_sim **out)
{
    plugin_host_ref h = {api, host};
    eco_random rnd = host_random(&h);
    plugin_err err = {0};
    plugin_params located = plugin_params_open(api, host, &st->located);
    eco_config cfg = st->cfg;
    const char *whence;
    int given = plugin_param_given(&located, "latitude");
    if (located.status) return located.status;
    cfg.factors.latitude_deg = eco_latitude_for(cfg.factors.latitude_deg, given, req, &whence);
    api->log(host, SYLVA_LOG_INFO, "ecology: the sun's path at latitude %.2f (%s)", cfg.factors.latitude_deg, whence);
    int rc = eco_sim_new(&rnd, &located, &cfg, st->only, req, out, &err);
    return rc ? plugin_params_report(&located, &err) : SYLVA_OK;
}

/* Simulates `years` more years with progress reports. */
static int run_years(eco_sim *sim, const sylva_host_api *api, sylva_host *host, uint32_t years)
{
    plugin_host_ref h = {api, host};
    eco_random rnd = host_random(&h);
    plugin_err err = {0};
    for (uint32_t y = 0; y < years; y++) {
        if (eco_sim_step(sim, &rnd, &err)) return plugin_report(api, host, &err);
        api->progress(host, "ecology", y + 1, years);
    }
    return SYLVA_OK;
}

/* ---- create, generate, destroy --------------------------------------------------------------- */

static void eco_destroy(void *state)
{
    eco_plugin_state *st = state;
    if (!st) return;
    free(st->mask), free(st->only), free(st->file), free(st->where);
    free(st);
}

/* Copies a list of whole numbers; -1 with a message when an element is not whole. */
static int whole_numbers(const sylva_host_api *api, sylva_host *host, const sylva_params *params, const char *key,
                         const sylva_value *v, uint32_t want, int64_t *out)
{
    if (v->len != 0 && v->len != want)
        return api->param_error(host, params, key, "'%s' holds %u numbers; give %u, or none", key, v->len, want);
    for (uint32_t i = 0; i < v->len; i++) {
        if (v->list[i] != floor(v->list[i]))
            return api->param_error(host, params, key, "element %u of '%s' is %g; it must be a whole number", i, key,
                                    v->list[i]);
        out[i] = (int64_t)v->list[i];
    }
    return SYLVA_OK;
}

static int eco_create(const sylva_host_api *api, sylva_host *host, const sylva_params *params, void **state)
{
    *state = NULL;
    eco_plugin_state *st = calloc(1, sizeof *st);
    if (!st) {
        api->error(host, "out of memory reading the ecology parameters");
        return SYLVA_ERR_NOMEM;
    }
    plugin_params r = plugin_params_open(api, host, params);
    eco_config *c = &st->cfg;
    eco_factor_params *f = &c->factors;
    f->patches = (uint32_t)plugin_param_int(&r, "patches");
    f->water_altitude = plugin_param_real(&r, "water_altitude");
    f->rain = plugin_param_real(&r, "rain");
    f->water_humidity = plugin_param_real(&r, "water_humidity");
    f->runoff = plugin_param_real(&r, "runoff");
    f->humidity_blur = (uint32_t)plugin_param_int(&r, "humidity_blur");
    f->wind_azimuth_deg = plugin_param_real(&r, "wind_azimuth");
    f->wind_samples = (uint32_t)plugin_param_int(&r, "wind_samples");
    f->shelter_deg = plugin_param_real(&r, "shelter_angle");
    f->latitude_deg = plugin_param_real(&r, "latitude");
    f->sun_samples = (uint32_t)plugin_param_int(&r, "sun_samples");
    f->ambient = plugin_param_real(&r, "ambient");
    int64_t threads = plugin_param_int(&r, "threads");
    /* The scene's own count, else the run's (--threads), else one per processor. */
    c->threads = threads > 0                     ? (unsigned)threads
                 : SYLVA_API_HAS(api, threads) ? api->threads(host)
                                               : plugin_threads_online();
    f->threads = c->threads;
    c->years = (uint32_t)plugin_param_int(&r, "years");
    c->max_plants = (uint64_t)plugin_param_int(&r, "max_plants");
    c->min_height = plugin_param_real(&r, "min_height");
    c->edge_fade = plugin_param_real(&r, "edge_fade");
    int rc = r.status; /* a name the schema lacks: the host has the sentence */
    if (rc) goto fail;
    if (f->sun_samples % 2 == 0) {
        rc = api->param_error(host, params, "sun_samples", "sun_samples = %u is even; give an odd number so that "
                              "one sample stands at noon (3, 5, 7, ...)", f->sun_samples);
        goto fail;
    }
    c->area[0] = -1;
    const sylva_value *area = plugin_param(&r, "growth_area");
    if ((rc = whole_numbers(api, host, params, "growth_area", area, 4, c->area))) goto fail;
    if (!area->len) c->area[0] = -1;
    int64_t seeds[ECO_N_SEEDED_STREAMS] = {0};
    if ((rc = whole_numbers(api, host, params, "stream_seeds", plugin_param(&r, "stream_seeds"),
                            ECO_N_SEEDED_STREAMS, seeds)))
        goto fail;
    for (int i = 0; i < ECO_N_SEEDED_STREAMS; i++) c->stream_seeds[i] = (uint64_t)seeds[i];
    const sylva_value *mask = plugin_param(&r, "growth_mask");
    if (mask->is_set && mask->rows && mask->cols) {
        size_t n = (size_t)mask->rows * mask->cols;
        if (!(st->mask = malloc(n * sizeof *st->mask))) goto nomem;
        memcpy(st->mask, mask->list, n * sizeof *st->mask);
        c->mask = st->mask, c->mask_rows = mask->rows, c->mask_cols = mask->cols;
    }
    const char *only = plugin_param_str(&r, "species");
    if ((rc = r.status)) goto fail;
    if (only && !(st->only = strdup(only))) goto nomem;
    if (params->file && !(st->file = strdup(params->file))) goto nomem;
    if (!(st->where = calloc(params->n ? params->n : 1, sizeof *st->where))) goto nomem;
    for (uint32_t i = 0; i < params->n; i++) {
        st->where[i].is_set = params->values[i].is_set;
        st->where[i].line = params->values[i].line, st->where[i].column = params->values[i].column;
    }
    st->located = (sylva_params){.spec = params->spec, .n = params->n, .values = st->where, .file = st->file,
                                 .line = params->line, .column = params->column};
    *state = st;
    return SYLVA_OK;
nomem:
    api->error(host, "out of memory reading the ecology parameters");
    rc = SYLVA_ERR_NOMEM;
fail:
    eco_destroy(st);
    return rc;
}

/* Hands the living plants of sim that are no seedlings (at least min_height) to the host. */
static int place_plants(const eco_sim *sim, double min_height, const sylva_host_api *api, sylva_host *host,
                        uint32_t *placed)
{
    *placed = 0;
    for (uint32_t j = 0; j < sim->n_species; j++) {
        const eco_species *sp = &sim->species[j];
        for (uint32_t q = 0; q < sim->pop[j].n; q++) {
            const eco_plant *pl = &sim->pop[j].plants[q];
            double height = pl->h * sim->model_height[j];
            if (!(pl->h > 0) || height < min_height) continue; /* a seedling */
            double age = pl->age / sp->t_a;
            sylva_plant p = {.size = sizeof p, .species = sim->request_index[j], .position = {pl->x, pl->y, pl->z},
                             .snap_to_terrain = 1, .rotation = pl->rotation,
                             .height = height, .age = age < 1e-6 ? 1e-6 : age > 1 ? 1 : age};
            int rc = api->plant_add(host, &p);
            if (rc) return rc;
            (*placed)++;
        }
    }
    return SYLVA_OK;
}

static int eco_generate(void *state, const sylva_host_api *api, sylva_host *host, const void *request, void *out)
{
    const eco_plugin_state *st = state;
    const sylva_ecology_request *req = request;
    sylva_ecology_out *o = out;
    if (!req || req->size < SYLVA_FIELD_END(sylva_ecology_request, n_species) || !o || o->size < sizeof *o)
        return api->error(host, "the ecology request or output is smaller than this plugin expects");
    o->n_plants = 0;
    eco_sim *sim = NULL;
    int rc = run_start(st, api, host, req, &sim);
    if (rc) return rc;
    if ((rc = run_years(sim, api, host, st->cfg.years))) goto done;
    if ((rc = place_plants(sim, st->cfg.min_height, api, host, &o->n_plants))) goto done;
    api->log(host, SYLVA_LOG_DEBUG, "%u plants placed after %u years", o->n_plants, sim->year);
done:
    eco_sim_free(sim);
    return rc;
}

/* ---- the "sylva.ecology.v1", "v2" and "v3" interfaces ------------------------------------------------------ */

static int run_new(void *state, const sylva_host_api *api, sylva_host *host, const sylva_ecology_request *req,
                   sylva_ecology_run **run)
{
    *run = NULL;
    const eco_plugin_state *st = state;
    if (!st || !req || req->size < SYLVA_FIELD_END(sylva_ecology_request, n_species))
        return api->error(host, "run_new needs the plugin's state and a request");
    sylva_ecology_run *r = calloc(1, sizeof *r);
    if (!r) {
        api->error(host, "out of memory starting the ecology");
        return SYLVA_ERR_NOMEM;
    }
    int rc = run_start(st, api, host, req, &r->sim);
    if (rc) {
        free(r);
        return rc;
    }
    r->years_wanted = st->cfg.years;
    r->min_height = st->cfg.min_height;
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
    return run_years(run->sim, api, host, years);
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
    plugin_err err = {0};
    return eco_sim_save(run->sim, path, &err) ? plugin_report(api, host, &err) : SYLVA_OK;
}

static int run_load(sylva_ecology_run *run, const sylva_host_api *api, sylva_host *host, const char *path)
{
    plugin_err err = {0};
    return eco_sim_load(run->sim, path, &err) ? plugin_report(api, host, &err) : SYLVA_OK;
}

static int run_place(const sylva_ecology_run *run, const sylva_host_api *api, sylva_host *host, uint32_t *placed)
{
    return place_plants(run->sim, run->min_height, api, host, placed);
}

static int run_planted_fate(const sylva_ecology_run *run, const sylva_host_api *api, sylva_host *host,
                            const sylva_ecology_planted *plants, uint32_t n, uint32_t years, uint64_t seed,
                            uint32_t *died)
{
    if (n && (!plants || !died)) return api->error(host, "planted_fate needs the plants and room for their deaths");
    plugin_host_ref h = {api, host};
    eco_random rnd = host_random(&h);
    plugin_err err = {0};
    return eco_planted_fate(run->sim, &rnd, plants, n, years, seed, died, &err) ? plugin_report(api, host, &err)
                                                                                 : SYLVA_OK;
}

/* v3's table; a request for v1 or v2 gets its part. */
static const sylva_ecology_ext_v3 eco_extension_v3 = {
    .v2 = {.v1 = {.size = sizeof(sylva_ecology_ext_v3),
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
           .load = run_load},
           .place = run_place},
    .planted_fate = run_planted_fate,
};

static const void *eco_extension(const char *id)
{
    if (!id) return NULL;
    if (!strcmp(id, SYLVA_ECOLOGY_EXT_V3)) return &eco_extension_v3;
    if (!strcmp(id, SYLVA_ECOLOGY_EXT_V2)) return &eco_extension_v3.v2;
    return !strcmp(id, SYLVA_ECOLOGY_EXT_V1) ? &eco_extension_v3.v2.v1 : NULL;
}

static const sylva_plugin eco_descriptor = {
    .size = sizeof(sylva_plugin),
    .abi_major = SYLVA_ABI_MAJOR,
    .abi_minor = SYLVA_ABI_MINOR,
    .param_spec_size = sizeof(sylva_param_spec),
    .kind = SYLVA_KIND_ECOLOGY,
    .name = "ecology",
    .summary = "Forest succession on the terrain by terrain factors, competition and seeding (Zamuda 2006).",
    .version = "1.0",
    .params = eco_params,
    .n_params = ECO_PARAMS,
    .species_section = "ecology",
    .species_params = eco_species_schema,
    .n_species_params = ECO_SPECIES_KEYS,
    .create = eco_create,
    .generate = eco_generate,
    .destroy = eco_destroy,
    .extension = eco_extension,
};

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    return index == 0 ? &eco_descriptor : (const sylva_plugin *)0;
}
