/* example_terrain.c — a small, complete terrain plugin: a seeded, bumpy heightfield.
 *
 * The terrain is a sum of EXAMPLE_BUMPS Gaussian hills on a flat plane, centred on the origin.
 * Where the hills stand, how wide and how high they are comes from the host's random stream
 * for this plugin, so the same scene seed gives the same terrain. docs/plugins.md walks through
 * this file; it includes nothing from sylva but sylva/plugin.h.
 */
#include <math.h>
#include <stdlib.h>

#include "sylva/plugin.h"

#define EXAMPLE_BUMPS 8
#define EXAMPLE_MAX_NODES (4096u * 4096u) /* the largest grid create() accepts */

static const sylva_param_spec example_params[] = {
    {.name = "nx", .type = SYLVA_P_INT, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX,
     .def = 65, .min = 2, .max = 4097, .help = "Grid nodes along x (west to east)."},
    {.name = "ny", .type = SYLVA_P_INT, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX,
     .def = 65, .min = 2, .max = 4097, .help = "Grid nodes along y (south to north)."},
    {.name = "node_spacing", .type = SYLVA_P_REAL,
     .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_MIN_EXCLUSIVE | SYLVA_PARAM_HAS_MAX, .def = 2.0,
     .min = 0.0, .max = 1000.0, .unit = "m", .help = "Distance between neighbouring nodes."},
    {.name = "amplitude", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX,
     .def = 5.0, .min = 0.0, .max = 1000.0, .unit = "m",
     .help = "Height of the tallest possible hill; each hill takes 30 to 100 percent of it."},
};

/* What create() keeps for generate(): the parameters, read once. Owned by the plugin. */
typedef struct example_state {
    uint32_t nx, ny;
    double spacing, amplitude;
} example_state;

static int example_create(const sylva_host_api *api, sylva_host *host, const sylva_params *params,
                          void **state)
{
    *state = NULL;
    /* The checked readers: a name the schema does not have is reported, never read as 0. */
    int64_t nx_given = 0, ny_given = 0;
    double spacing = 0, amplitude = 0;
    int rc = sylva_param_int_checked(api, host, params, "nx", &nx_given);
    if (!rc) rc = sylva_param_int_checked(api, host, params, "ny", &ny_given);
    if (!rc) rc = sylva_param_real_checked(api, host, params, "node_spacing", &spacing);
    if (!rc) rc = sylva_param_real_checked(api, host, params, "amplitude", &amplitude);
    if (rc) return rc;
    uint32_t nx = (uint32_t)nx_given, ny = (uint32_t)ny_given;
    /* The schema bounds each side; only the product needs a check of its own. */
    if ((uint64_t)nx * ny > EXAMPLE_MAX_NODES)
        return api->param_error(host, params, "ny", "nx * ny = %u * %u nodes is more than this "
                                "plugin builds (%u); lower nx or ny", nx, ny, EXAMPLE_MAX_NODES);
    example_state *s = malloc(sizeof *s); /* owned by the plugin until example_destroy */
    if (!s) {
        api->error(host, "example_terrain: out of memory for its settings");
        return SYLVA_ERR_NOMEM;
    }
    s->nx = nx;
    s->ny = ny;
    s->spacing = spacing;
    s->amplitude = amplitude;
    *state = s;
    return SYLVA_OK;
}

static int example_generate(void *state, const sylva_host_api *api, sylva_host *host,
                            const void *request, void *out)
{
    const example_state *s = state;
    sylva_terrain_out *o = out;
    (void)request; /* the scene seed reaches us through api->rng_init */
    if (o->size < offsetof(sylva_terrain_out, terrain) + sizeof o->terrain) {
        api->error(host, "example_terrain: the host's terrain output is too small (%u bytes)",
                   o->size);
        return SYLVA_ERR_INTERNAL;
    }

    sylva_heightfield *hf = api->heightfield_new(host, s->nx, s->ny, 0); /* owned by the host */
    if (!hf) {
        api->error(host, "example_terrain: cannot allocate a %u x %u heightfield", s->nx, s->ny);
        return SYLVA_ERR_NOMEM;
    }
    double width = (s->nx - 1) * s->spacing, depth = (s->ny - 1) * s->spacing;
    hf->dx = hf->dy = s->spacing;
    hf->x0 = -0.5 * width;
    hf->y0 = -0.5 * depth;

    /* Each hill: a centre anywhere on the grid, a width of 5 to 20 percent of the shorter side,
     * a height of 30 to 100 percent of the amplitude. */
    double cx[EXAMPLE_BUMPS], cy[EXAMPLE_BUMPS], sigma[EXAMPLE_BUMPS], height[EXAMPLE_BUMPS];
    double side = width < depth ? width : depth;
    sylva_rng rng;
    api->rng_init(host, &rng, "example_terrain.hills", 0);
    for (int k = 0; k < EXAMPLE_BUMPS; k++) {
        cx[k] = hf->x0 + width * api->rng_uniform(&rng);
        cy[k] = hf->y0 + depth * api->rng_uniform(&rng);
        sigma[k] = side * (0.05 + 0.15 * api->rng_uniform(&rng));
        height[k] = s->amplitude * (0.3 + 0.7 * api->rng_uniform(&rng));
    }

    for (uint32_t j = 0; j < s->ny; j++) {
        double y = hf->y0 + j * s->spacing;
        for (uint32_t i = 0; i < s->nx; i++) {
            double x = hf->x0 + i * s->spacing, z = 0.0;
            for (int k = 0; k < EXAMPLE_BUMPS; k++) {
                double rx = x - cx[k], ry = y - cy[k];
                z += height[k] * exp(-(rx * rx + ry * ry) / (2.0 * sigma[k] * sigma[k]));
            }
            hf->z[(size_t)j * s->nx + i] = (float)z;
        }
        api->progress(host, "example_terrain hills", j + 1, s->ny);
    }
    o->terrain = hf;
    return SYLVA_OK;
}

static void example_destroy(void *state) { free(state); }

static const sylva_plugin example_terrain = {
    .size = sizeof(sylva_plugin),
    .abi_major = SYLVA_ABI_MAJOR,
    .abi_minor = SYLVA_ABI_MINOR,
    .param_spec_size = sizeof(sylva_param_spec),
    .kind = SYLVA_KIND_TERRAIN,
    .name = "example_terrain",
    .summary = "Gaussian hills on a flat plane, placed from the scene seed.",
    .version = "1.0",
    .params = example_params,
    .n_params = sizeof example_params / sizeof example_params[0],
    .create = example_create,
    .generate = example_generate,
    .destroy = example_destroy,
};

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    return index == 0 ? &example_terrain : NULL;
}
