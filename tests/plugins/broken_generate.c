/* broken_generate.c — a test terrain plugin that fails half-way through generate(): it takes a
 * heightfield from the host, fills the southern half of the rows, hands it out and then returns
 * an error through api->error. The host must report the sentence, release the partial output
 * with the rest of the scene, still call destroy() on the state, and write no image. */
#include <stdlib.h>

#include "sylva/plugin.h"

static const sylva_param_spec broken_generate_params[] = {
    {.name = "n", .type = SYLVA_P_INT, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX,
     .def = 16, .min = 2, .max = 1024, .help = "Grid nodes along x and y."},
};

typedef struct broken_generate_state {
    uint32_t n;
} broken_generate_state;

static int broken_generate_create(const sylva_host_api *api, sylva_host *host,
                                  const sylva_params *params, void **state)
{
    broken_generate_state *s = malloc(sizeof *s); /* owned by the plugin until destroy() */
    *state = s;
    if (!s) {
        api->error(host, "broken_generate: out of memory for its settings");
        return SYLVA_ERR_NOMEM;
    }
    s->n = (uint32_t)sylva_param_int(params, "n");
    return SYLVA_OK;
}

static int broken_generate_generate(void *state, const sylva_host_api *api, sylva_host *host,
                                    const void *request, void *out)
{
    const broken_generate_state *s = state;
    sylva_heightfield *hf = api->heightfield_new(host, s->n, s->n, 0); /* owned by the host */
    if (!hf) {
        api->error(host, "broken_generate: cannot allocate a %u x %u heightfield", s->n, s->n);
        return SYLVA_ERR_NOMEM;
    }
    hf->dx = hf->dy = 1.0;
    uint32_t rows = s->n / 2;
    for (uint32_t j = 0; j < rows; j++)
        for (uint32_t i = 0; i < s->n; i++) hf->z[(size_t)j * s->n + i] = (float)j;
    ((sylva_terrain_out *)out)->terrain = hf;
    api->error(host, "broken_generate: stopped after row %u of %u, deliberately, to test how the "
               "host handles a plugin that fails with partial output", rows, s->n);
    return SYLVA_ERR_INTERNAL;
}

static void broken_generate_destroy(void *state) { free(state); }

static const sylva_plugin broken_generate = {
    .size = sizeof(sylva_plugin),
    .abi_major = SYLVA_ABI_MAJOR,
    .abi_minor = SYLVA_ABI_MINOR,
    .param_spec_size = sizeof(sylva_param_spec),
    .kind = SYLVA_KIND_TERRAIN,
    .name = "broken_generate",
    .summary = "A terrain whose generate() fails half-way (for tests).",
    .version = "1.0",
    .params = broken_generate_params,
    .n_params = 1,
    .create = broken_generate_create,
    .generate = broken_generate_generate,
    .destroy = broken_generate_destroy,
};

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    return index == 0 ? &broken_generate : NULL;
}
