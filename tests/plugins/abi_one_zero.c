/* abi_one_zero.c — a terrain plugin laid out as ABI 1.0 defined it: minor 0, the 1.0
 * descriptor size (no preset fields) and only the host functions of 1.0 (it checks that the
 * table reaches at least that far). A 1.1 host must load and run it unchanged: a plateau of
 * `height` metres. */
#include <stdlib.h>

#include "sylva/plugin.h"

static const sylva_param_spec abi_params[] = {
    {.name = "height", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX,
     .def = 2, .min = 0, .max = 100, .unit = "m", .help = "Height of the plateau."},
};

typedef struct plateau {
    double height;
} plateau;

static int abi_create(const sylva_host_api *api, sylva_host *host, const sylva_params *params,
                      void **state)
{
    if (api->size < SYLVA_HOST_API_SIZE_1_0) return SYLVA_ERR_INTERNAL;
    plateau *p = malloc(sizeof *p); /* owned by the plugin until abi_destroy */
    if (!p) return api->error(host, "abi_one_zero: out of memory"), SYLVA_ERR_NOMEM;
    p->height = sylva_param_real(params, "height");
    *state = p;
    return SYLVA_OK;
}

static int abi_generate(void *state, const sylva_host_api *api, sylva_host *host,
                        const void *request, void *out)
{
    const plateau *p = state;
    sylva_heightfield *hf = api->heightfield_new(host, 3, 3, 0); /* owned by the host */
    if (!hf) return api->error(host, "cannot allocate a 3 x 3 heightfield");
    hf->x0 = hf->y0 = -10, hf->dx = hf->dy = 10;
    for (int i = 0; i < 9; i++) hf->z[i] = (float)p->height;
    ((sylva_terrain_out *)out)->terrain = hf;
    return SYLVA_OK;
}

static void abi_destroy(void *state) { free(state); }

static const sylva_plugin abi_one_zero = {
    .size = (uint32_t)SYLVA_PLUGIN_SIZE_1_0,
    .abi_major = 1,
    .abi_minor = 0,
    .param_spec_size = sizeof(sylva_param_spec),
    .kind = SYLVA_KIND_TERRAIN,
    .name = "abi_one_zero",
    .summary = "A plateau from a plugin built against ABI 1.0.",
    .version = "1.0",
    .params = abi_params,
    .n_params = 1,
    .create = abi_create,
    .generate = abi_generate,
    .destroy = abi_destroy,
};

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    return index == 0 ? &abi_one_zero : NULL;
}
