/* flat_terrain_ops.h — the operations of a minimal valid terrain plugin (a flat 2 x 2
 * heightfield), shared by the test modules whose descriptors are broken on purpose: their flaw is
 * in the descriptor, never here. */
#ifndef SYLVA_TEST_FLAT_TERRAIN_OPS_H
#define SYLVA_TEST_FLAT_TERRAIN_OPS_H

#include "sylva/plugin.h"

static int flat_create(const sylva_host_api *api, sylva_host *host, const sylva_params *params,
                       void **state)
{
    *state = NULL;
    return SYLVA_OK;
}

static int flat_generate(void *state, const sylva_host_api *api, sylva_host *host,
                         const void *request, void *out)
{
    sylva_heightfield *hf = api->heightfield_new(host, 2, 2, 0); /* owned by the host */
    if (!hf) return api->error(host, "cannot allocate a 2 x 2 heightfield");
    hf->dx = hf->dy = 1.0;
    ((sylva_terrain_out *)out)->terrain = hf;
    return SYLVA_OK;
}

static void flat_destroy(void *state) { (void)state; }

#endif
