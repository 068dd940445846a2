/* eco_habitat.c — where each species may take root, from the host's land cover (ABI 1.7: the
 * request's habitat rows, one byte per node of the surveyed terrain): each patch takes the value
 * at the node nearest its centre, so a species' community grows where the land-cover map has it
 * and nowhere else (docs/models/ecology.md, "Land cover"). */
#include <math.h>
#include <stdlib.h>

#include "eco_sim.h"

/* The node of hf nearest to (x, y), clamped to the grid. */
static size_t nearest_node(const sylva_heightfield *hf, double x, double y)
{
    double fi = round((x - hf->x0) / hf->dx), fj = round((y - hf->y0) / hf->dy);
    fi = fi < 0 ? 0 : fi > hf->nx - 1 ? hf->nx - 1 : fi;
    fj = fj < 0 ? 0 : fj > hf->ny - 1 ? hf->ny - 1 : fj;
    return (size_t)fj * hf->nx + (size_t)fi;
}

int eco_habitat_build(eco_sim *s, const sylva_ecology_request *req, plugin_err *err)
{
    if (!SYLVA_HAS_FIELD(req, sylva_ecology_request, habitat) || !req->habitat) return SYLVA_OK;
    const eco_terrain *t = &s->terrain;
    const sylva_heightfield *hf = req->terrain;
    size_t n = (size_t)t->ni * t->nk;
    if (!(s->habitat = calloc(s->n_species ? s->n_species : 1, sizeof *s->habitat)))
        return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for the species' habitats");
    for (uint32_t j = 0; j < s->n_species; j++) {
        const uint8_t *row = req->habitat[s->request_index[j]];
        if (!row) continue;
        if (!(s->habitat[j] = malloc(n)))
            return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for the habitat of '%s'", s->names[j]);
        for (uint32_t k = 0; k < t->nk; k++)
            for (uint32_t i = 0; i < t->ni; i++)
                s->habitat[j][(size_t)k * t->ni + i] =
                    row[nearest_node(hf, t->x0 + (i + 0.5) * t->kx, t->y0 + (k + 0.5) * t->ky)] != 0;
    }
    return SYLVA_OK;
}
