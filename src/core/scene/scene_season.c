/* scene_season.c — leaf-off prototypes for the species out of leaf on the scene's day
 * (scene_season.h). */
#include "scene/scene_season.h"

#include <string.h>

uint32_t scene_drop_leaves(const scene *s, mesh *m)
{
    uint32_t kept = 0;
    for (uint32_t t = 0; t < m->nt; t++) {
        if (s->materials[scene_triangle_material(s, m, t)].bsdf == SYLVA_BSDF_LEAF) continue;
        if (kept != t) {
            memcpy(m->tri + (size_t)kept * 3, m->tri + (size_t)t * 3, 3 * sizeof *m->tri);
            m->mat[kept] = m->mat[t];
        }
        kept++;
    }
    uint32_t dropped = m->nt - kept;
    m->nt = kept;
    return dropped;
}

int scene_apply_season(scene *s, const scene_file *sf)
{
    /* scene_build makes scene species i from scene-file species i; ground cover comes after */
    for (uint32_t i = 0; i < sf->n_species && i < s->n_species; i++) {
        if (phenology_in_leaf(&sf->species[i].phenology, sf->season.day)) continue;
        const species *sp = &s->species[i];
        for (uint32_t v = 0; v < sp->n_variants; v++) scene_drop_leaves(s, s->prototypes[sp->first_prototype + v].mesh);
    }
    return 0;
}
