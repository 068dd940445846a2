/* eco_fixture.h — what the ecology tests share: synthetic heightfields, a real host (the core's
 * API table) for random streams and messages, species blocks with chosen keys, the default run
 * configuration, and starting a run on them. */
#ifndef ECO_FIXTURE_H
#define ECO_FIXTURE_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "eco_schema.h"
#include "eco_sim.h"
#include "eco_species.h"
#include "harness.h"
#include "scene_build/host.h"

/* A heightfield of nx x ny nodes `spacing` apart starting at (x0, y0), heights from z(x, y). */
typedef double (*eco_height_fn)(double x, double y);

static inline sylva_heightfield fixture_heightfield(uint32_t nx, uint32_t ny, double x0, double y0, double spacing,
                                             eco_height_fn z)
{
    sylva_heightfield hf = {.size = sizeof hf, .nx = nx, .ny = ny, .x0 = x0, .y0 = y0, .dx = spacing,
                            .dy = spacing, .water_material = -1};
    hf.z = malloc((size_t)nx * ny * sizeof *hf.z);
    for (uint32_t j = 0; j < ny; j++)
        for (uint32_t i = 0; i < nx; i++) hf.z[(size_t)j * nx + i] = (float)z(x0 + i * spacing, y0 + j * spacing);
    return hf;
}

/* The factor parameters of the plugin's defaults. */
static inline eco_factor_params fixture_factor_params(uint32_t patches)
{
    return (eco_factor_params){.patches = patches, .water_altitude = 0, .rain = 1, .water_humidity = 10,
                               .runoff = 1, .humidity_blur = 10, .wind_azimuth_deg = 270, .wind_samples = 10,
                               .shelter_deg = 45, .latitude_deg = 46, .sun_samples = 9, .ambient = 0.2,
                               .threads = 1};
}

static inline eco_config fixture_config(uint32_t patches)
{
    eco_config c = {.factors = fixture_factor_params(patches), .years = 0, .area = {-1, 0, 0, 0},
                    .max_plants = 5000000, .threads = 1, .min_height = 0};
    return c;
}

/* A host like the one scene_build gives an ecology plugin, and the model's random source made of
 * its streams (as the plugin file makes it). */
typedef struct fixture_host {
    scene *scene;
    sylva_host host;
    err_buf err;
    const sylva_host_api *api;
    eco_random rnd;  /* ctx: this fixture */
    plugin_err fail;    /* the model's last failure */
} fixture_host;

static inline void fixture_stream(void *ctx, sylva_rng *rng, const char *purpose, uint64_t index)
{
    fixture_host *f = ctx;
    f->api->rng_init(&f->host, rng, purpose, index);
}

static inline void fixture_host_init(fixture_host *f, uint64_t seed)
{
    memset(f, 0, sizeof *f);
    f->scene = scene_new();
    host_init(&f->host, f->scene, "/tmp", seed, "ecology plugin 'ecology'", &f->err);
    f->host.kind = SYLVA_KIND_ECOLOGY;
    f->host.quiet = 1;
    f->api = host_api_table();
    f->rnd = (eco_random){.stream = fixture_stream, .uniform = f->api->rng_uniform, .ctx = f};
}

static inline void fixture_host_release(fixture_host *f)
{
    host_release(&f->host);
    scene_free(f->scene);
}

/* A reader of `block` (NULL: none) through the fixture's host, as the plugin file makes one. */
static inline plugin_params fixture_reader(fixture_host *f, const sylva_params *block)
{
    return plugin_params_open(f->api, &f->host, block);
}

/* eco_species_read of `block` (NULL: none) through the fixture's host. */
static inline int fixture_species_read(fixture_host *f, const sylva_params *block, const char *name,
                                       eco_species *out)
{
    plugin_params r = fixture_reader(f, block);
    return eco_species_read(&r, name, out, &f->fail);
}

/* A species block with every key at its schema default, then `keys` (NULL-terminated names)
 * set to `values`. The block's values live in the returned struct (free with free()). */
typedef struct fixture_block {
    sylva_params params;
    sylva_value values[ECO_SPECIES_KEYS];
} fixture_block;

static inline fixture_block *fixture_species_block(const char *const *keys, const double *values)
{
    fixture_block *b = calloc(1, sizeof *b);
    for (uint32_t i = 0; i < ECO_SPECIES_KEYS; i++) {
        const sylva_param_spec *s = &eco_species_schema[i];
        b->values[i].r = s->def, b->values[i].i = (int64_t)s->def, b->values[i].s = s->def_str;
    }
    for (int k = 0; keys && keys[k]; k++)
        for (uint32_t i = 0; i < ECO_SPECIES_KEYS; i++)
            if (!strcmp(eco_species_schema[i].name, keys[k])) {
                b->values[i].is_set = 1, b->values[i].r = values[k], b->values[i].i = (int64_t)values[k];
                b->values[i].line = 10 + i, b->values[i].column = 7;
            }
    b->params = (sylva_params){.spec = eco_species_schema, .n = ECO_SPECIES_KEYS, .values = b->values,
                               .file = "species.yaml", .line = 9, .column = 5};
    return b;
}

/* Starts a run on hf for species `names` with blocks (entries may be NULL: profile by name). */
static inline int fixture_sim(fixture_host *f, const sylva_heightfield *hf, const eco_config *cfg, uint32_t n,
                       const char *const *names, fixture_block *const *blocks, eco_sim **out)
{
    sylva_species_info info[8];
    for (uint32_t i = 0; i < n; i++)
        info[i] = (sylva_species_info){.size = sizeof info[i], .name = names[i],
                                       .ecology = blocks && blocks[i] ? &blocks[i]->params : NULL,
                                       .model_height = 10};
    sylva_ecology_request req = {.size = sizeof req, .seed = f->host.seed, .terrain = hf, .species = info,
                                 .n_species = n};
    f->host.n_species = n;
    plugin_params r = fixture_reader(f, NULL);
    return eco_sim_new(&f->rnd, &r, cfg, NULL, &req, out, &f->fail);
}

/* 1 when two runs hold the same plants, field by field, in the same order. */
static inline int fixture_same_plants(const eco_sim *a, const eco_sim *b)
{
    if (a->n_species != b->n_species || a->year != b->year) return 0;
    for (uint32_t j = 0; j < a->n_species; j++) {
        if (a->pop[j].n != b->pop[j].n) return 0;
        for (uint32_t q = 0; q < a->pop[j].n; q++) {
            const eco_plant *p = &a->pop[j].plants[q], *r = &b->pop[j].plants[q];
            if (p->x != r->x || p->y != r->y || p->z != r->z || p->h != r->h || p->r != r->r || p->power != r->power ||
                p->v != r->v || p->t_max != r->t_max || p->rotation != r->rotation || p->age != r->age ||
                p->patch != r->patch || p->dominated != r->dominated)
                return 0;
        }
    }
    return 1;
}

#endif
