/* ecology.c — the `ecology` plugin: its descriptor, the schema of the scene's `ecology:` block
 * and of each species' `ecology:` block, and create() / generate() / destroy(). generate()
 * simulates the scene's years (eco_sim.h) and adds every living plant that has grown through
 * api->plant_add: its position, a turn about the vertical, its height in metres (the normalised
 * height times the species' model height) and its normalised age t / t_a, which picks the
 * species' age variant. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "eco_plugin.h"
#include "eco_species.h"
#include "eco_parallel.h"

#define RANGE (SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX)

const sylva_param_spec eco_params[] = {
    {.name = "years", .type = SYLVA_P_INT, .flags = RANGE, .def = 180, .min = 0, .max = 100000, .unit = "years",
     .help = "Years of succession to simulate from bare land."},
    {.name = "species", .type = SYLVA_P_STRING,
     .help = "Species that take part, by name, separated by commas or spaces; empty: every species of the scene."},
    {.name = "patches", .type = SYLVA_P_INT, .flags = RANGE, .def = 100, .min = 2, .max = 2048,
     .help = "Patches of the factor grid along the terrain's longer side (the thesis uses 100)."},
    {.name = "growth_area", .type = SYLVA_P_LIST, .flags = SYLVA_PARAM_HAS_MIN, .min = 0, .max_len = 4,
     .help = "Patch rectangle [i0, k0, i1, k1] (whole numbers, inclusive, i west to east, k south to north) "
             "where plants may grow; empty: the whole terrain."},
    {.name = "growth_mask", .type = SYLVA_P_GRID,
     .help = "Rows (south to north) of cells over the whole terrain; plants grow only on patches whose centre "
             "falls in a non-zero cell."},
    {.name = "water_altitude", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0, .min = 0, .max = 1,
     .help = "Normalised altitude below which patches are water (0: only the terrain's own water surface)."},
    {.name = "rain", .type = SYLVA_P_REAL, .flags = RANGE, .def = 1, .min = 0, .max = 1000,
     .help = "Precipitation every patch receives, m_climate."},
    {.name = "water_humidity", .type = SYLVA_P_REAL, .flags = RANGE, .def = 10, .min = 0, .max = 1000000,
     .help = "Humidity added to water patches, m_w."},
    {.name = "runoff", .type = SYLVA_P_REAL, .flags = RANGE, .def = 1, .min = 0, .max = 1,
     .help = "Runoff strength k_m: share of a patch's water times its slope that flows to lower patches."},
    {.name = "humidity_blur", .type = SYLVA_P_INT, .flags = RANGE, .def = 10, .min = 0, .max = 1000,
     .help = "Passes of the 5-point average over the humidity, N_mblur."},
    {.name = "wind_azimuth", .type = SYLVA_P_REAL, .flags = RANGE, .def = 270, .min = -360, .max = 360,
     .unit = "deg", .help = "Direction the wind comes from, clockwise from north (270: from the west)."},
    {.name = "wind_samples", .type = SYLVA_P_INT, .flags = RANGE, .def = 10, .min = 1, .max = 1000,
     .help = "Patches marched upwind to find a patch's shelter, N_w."},
    {.name = "shelter_angle", .type = SYLVA_P_REAL,
     .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_MIN_EXCLUSIVE | SYLVA_PARAM_HAS_MAX, .def = 45, .min = 0, .max = 90,
     .unit = "deg", .help = "Shelter angle at which a patch is out of the wind entirely, Theta_0."},
    {.name = "latitude", .type = SYLVA_P_REAL, .flags = RANGE, .def = 46, .min = -80, .max = 80, .unit = "deg",
     .help = "Latitude of the terrain (north positive); sets the summer sun's path."},
    {.name = "sun_samples", .type = SYLVA_P_INT, .flags = RANGE, .def = 9, .min = 3, .max = 101,
     .help = "Sun positions along the day, an odd number, N_l."},
    {.name = "ambient", .type = SYLVA_P_REAL,
     .flags = RANGE | SYLVA_PARAM_MIN_EXCLUSIVE | SYLVA_PARAM_MAX_EXCLUSIVE, .def = 0.2, .min = 0, .max = 1,
     .help = "Share of the light a patch gets in shadow or facing away from the sun, l_ambient."},
    {.name = "stream_seeds", .type = SYLVA_P_LIST, .flags = RANGE, .min = 0, .max = 9007199254740992.0,
     .max_len = 13,
     .help = "Seeds of the 13 random streams (near, parent, side, anywhere, position i, position j, death by "
             "dominance, altitude, humidity, sunniness, windiness, slope, death age); empty: all 0."},
    {.name = "min_height", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0.5, .min = 0, .max = 1000, .unit = "m",
     .help = "Plants shorter than this are left out of the scene (they still live in the simulation)."},
    {.name = "max_plants", .type = SYLVA_P_INT, .flags = RANGE, .def = 5000000, .min = 1, .max = 100000000,
     .help = "Most living plants the simulation may hold; more is an error."},
    {.name = "threads", .type = SYLVA_P_INT, .flags = RANGE, .def = 0, .min = 0, .max = 256,
     .help = "Worker threads (0: one per processor); the forest does not depend on it."},
};
const uint32_t eco_params_count = sizeof eco_params / sizeof eco_params[0];

void eco_destroy(void *state)
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

int eco_create(const sylva_host_api *api, sylva_host *host, const sylva_params *params, void **state)
{
    *state = NULL;
    eco_plugin_state *st = calloc(1, sizeof *st);
    if (!st) return api->error(host, "out of memory");
    eco_config *c = &st->cfg;
    eco_factor_params *f = &c->factors;
    f->patches = (uint32_t)sylva_param_int(params, "patches");
    f->water_altitude = sylva_param_real(params, "water_altitude");
    f->rain = sylva_param_real(params, "rain");
    f->water_humidity = sylva_param_real(params, "water_humidity");
    f->runoff = sylva_param_real(params, "runoff");
    f->humidity_blur = (uint32_t)sylva_param_int(params, "humidity_blur");
    f->wind_azimuth_deg = sylva_param_real(params, "wind_azimuth");
    f->wind_samples = (uint32_t)sylva_param_int(params, "wind_samples");
    f->shelter_deg = sylva_param_real(params, "shelter_angle");
    f->latitude_deg = sylva_param_real(params, "latitude");
    f->sun_samples = (uint32_t)sylva_param_int(params, "sun_samples");
    f->ambient = sylva_param_real(params, "ambient");
    int64_t threads = sylva_param_int(params, "threads");
    c->threads = threads > 0 ? (unsigned)threads : eco_cpu_count();
    f->threads = c->threads;
    c->years = (uint32_t)sylva_param_int(params, "years");
    c->max_plants = (uint64_t)sylva_param_int(params, "max_plants");
    c->min_height = sylva_param_real(params, "min_height");
    int rc = SYLVA_OK;
    if (f->sun_samples % 2 == 0) {
        rc = api->param_error(host, params, "sun_samples", "sun_samples = %u is even; give an odd number so that "
                              "one sample stands at noon (3, 5, 7, ...)", f->sun_samples);
        goto fail;
    }
    c->area[0] = -1;
    const sylva_value *area = sylva_param(params, "growth_area");
    if ((rc = whole_numbers(api, host, params, "growth_area", area, 4, c->area))) goto fail;
    if (!area->len) c->area[0] = -1;
    int64_t seeds[ECO_N_SEEDED_STREAMS] = {0};
    if ((rc = whole_numbers(api, host, params, "stream_seeds", sylva_param(params, "stream_seeds"),
                            ECO_N_SEEDED_STREAMS, seeds)))
        goto fail;
    for (int i = 0; i < ECO_N_SEEDED_STREAMS; i++) c->stream_seeds[i] = (uint64_t)seeds[i];
    const sylva_value *mask = sylva_param(params, "growth_mask");
    if (mask->is_set && mask->rows && mask->cols) {
        size_t n = (size_t)mask->rows * mask->cols;
        if (!(st->mask = malloc(n * sizeof *st->mask))) goto nomem;
        memcpy(st->mask, mask->list, n * sizeof *st->mask);
        c->mask = st->mask, c->mask_rows = mask->rows, c->mask_cols = mask->cols;
    }
    const char *only = sylva_param_str(params, "species");
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
    rc = api->error(host, "out of memory reading the ecology parameters");
fail:
    eco_destroy(st);
    return rc;
}

int eco_generate(void *state, const sylva_host_api *api, sylva_host *host, const void *request, void *out)
{
    const eco_plugin_state *st = state;
    const sylva_ecology_request *req = request;
    sylva_ecology_out *o = out;
    if (!req || req->size < sizeof *req || !o || o->size < sizeof *o)
        return api->error(host, "the ecology request or output is smaller than this plugin expects");
    o->n_plants = 0;
    eco_sim *sim = NULL;
    int rc = eco_run_start(st, api, host, req, &sim);
    if (rc) return rc;
    if ((rc = eco_run_years(sim, api, host, st->cfg.years))) goto done;
    for (uint32_t j = 0; j < sim->n_species; j++) {
        const eco_species *sp = &sim->species[j];
        for (uint32_t q = 0; q < sim->pop[j].n; q++) {
            const eco_plant *pl = &sim->pop[j].plants[q];
            double height = pl->h * sim->model_height[j];
            if (!(pl->h > 0) || height < st->cfg.min_height) continue; /* a seedling */
            double age = pl->age / sp->t_a;
            sylva_plant p = {.size = sizeof p, .species = sim->request_index[j], .position = {pl->x, pl->y, pl->z},
                             .snap_to_terrain = 1, .rotation = pl->rotation,
                             .height = height, .age = age < 1e-6 ? 1e-6 : age > 1 ? 1 : age};
            if ((rc = api->plant_add(host, &p))) goto done;
            o->n_plants++;
        }
    }
    api->log(host, SYLVA_LOG_DEBUG, "%u plants placed after %u years", o->n_plants, sim->year);
done:
    eco_sim_free(sim);
    return rc;
}

static const void *eco_extension(const char *id)
{
    return id && !strcmp(id, SYLVA_ECOLOGY_EXT_V1) ? &eco_extension_v1 : NULL;
}

const sylva_plugin eco_descriptor = {
    .size = sizeof(sylva_plugin),
    .abi_major = SYLVA_ABI_MAJOR,
    .abi_minor = SYLVA_ABI_MINOR,
    .param_spec_size = sizeof(sylva_param_spec),
    .kind = SYLVA_KIND_ECOLOGY,
    .name = "ecology",
    .summary = "Forest succession on the terrain by terrain factors, competition and seeding (Zamuda 2006).",
    .version = "1.0",
    .params = eco_params,
    .n_params = sizeof eco_params / sizeof eco_params[0],
    .species_section = "ecology",
    .species_params = eco_species_schema,
    .n_species_params = ECO_SPECIES_KEYS,
    .create = eco_create,
    .generate = eco_generate,
    .destroy = eco_destroy,
    .extension = eco_extension,
};
