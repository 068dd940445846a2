/* ecology_habitat.c — the land cover's communities as the ecology's habitats (ecology_habitat.h). */
#include "scene_build/ecology_habitat.h"

#include <stdlib.h>

#include "scene_build/scene_communities.h"

void ecology_habitat_free(uint8_t **rows, uint32_t n)
{
    for (uint32_t i = 0; rows && i < n; i++) free(rows[i]);
    free(rows);
}

/* Species sp's row: 1 on the nodes whose class grows a community naming sp. */
static void fill_row(const land_cover *lc, const landcover_spec *spec, const int32_t *community, uint32_t sp,
                     uint8_t *row)
{
    size_t n = (size_t)lc->nx * lc->ny;
    for (size_t i = 0; i < n; i++) {
        uint16_t c = lc->node_class[i];
        int32_t m = c == LAND_COVER_NONE ? -1 : community[c];
        row[i] = 0;
        for (uint32_t k = 0; m >= 0 && k < spec->communities[m].n_species; k++)
            row[i] |= spec->communities[m].species[k] == sp;
    }
}

/* 1 when a community names species sp. */
static int named(const landcover_spec *spec, uint32_t sp)
{
    for (uint32_t m = 0; m < spec->n_communities; m++)
        for (uint32_t k = 0; k < spec->communities[m].n_species; k++)
            if (spec->communities[m].species[k] == sp) return 1;
    return 0;
}

uint8_t **ecology_habitat_new(const scene *s, const scene_file *sf, err_buf *err)
{
    const landcover_spec *spec = &sf->landcover;
    const land_cover *lc = s->land_cover;
    if (!lc || !spec->n_communities || !sf->n_species) return NULL;
    uint8_t **rows = calloc(sf->n_species, sizeof *rows);            /* the caller's */
    int32_t *community = malloc(lc->n_classes * sizeof *community);  /* owned here */
    int ok = rows && community;
    for (uint32_t c = 0; ok && c < lc->n_classes; c++) community[c] = landcover_community_of(spec, &lc->classes[c]);
    for (uint32_t sp = 0; ok && sp < sf->n_species; sp++) {
        if (!named(spec, sp)) continue;
        if (!(rows[sp] = malloc((size_t)lc->nx * lc->ny))) ok = 0;
        else fill_row(lc, spec, community, sp, rows[sp]);
    }
    free(community);
    if (ok) return rows;
    ecology_habitat_free(rows, rows ? sf->n_species : 0);
    err_nomem(err, "out of memory for the ecology's habitats from the land cover");
    return NULL;
}
