/* scene_season.c — leaf-off prototypes for the species out of leaf on the scene's day, and
 * autumn leaf materials and the leaves already down for the species whose leaves are turning
 * (scene_season.h). */
#include "season/scene_season.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/rng.h"

/* Moves triangle t of m (its vertices and material) to place `kept`, at or before t, as a mesh
 * is compacted in order. */
static void keep_triangle(mesh *m, uint32_t t, uint32_t kept)
{
    if (kept == t) return;
    memcpy(m->tri + (size_t)kept * 3, m->tri + (size_t)t * 3, 3 * sizeof *m->tri);
    m->mat[kept] = m->mat[t];
}

uint32_t scene_drop_leaves(const scene *s, mesh *m)
{
    uint32_t kept = 0;
    for (uint32_t t = 0; t < m->nt; t++) {
        if (s->materials[scene_triangle_material(s, m, t)].bsdf == SYLVA_BSDF_LEAF) continue;
        keep_triangle(m, t, kept++);
    }
    uint32_t dropped = m->nt - kept;
    m->nt = kept;
    return dropped;
}

/* A copy of leaf material id turned share f of the way toward colour c, named with `label` (the
 * transmittance keeps its ratio to the albedo, within what the albedo leaves of the light). */
static int32_t turned_material(scene *s, uint32_t id, const char *species_name, const char *label, const double c[3],
                               double f, err_buf *err)
{
    const material old = s->materials[id]; /* a copy: adding a material may move the array */
    char name[256];
    snprintf(name, sizeof name, "%s (%s, %s)", old.name, species_name, label);
    sylva_material_desc d = {.size = sizeof d, .name = name, .bsdf = SYLVA_BSDF_LEAF, .texture = old.texture,
                             .alpha_mask = old.alpha_mask};
    const double a[3] = {old.albedo.x, old.albedo.y, old.albedo.z};
    const double t[3] = {old.transmittance.x, old.transmittance.y, old.transmittance.z};
    for (int k = 0; k < 3; k++) {
        double turned = a[k] + f * (c[k] - a[k]);
        double through = a[k] > 0 ? t[k] * turned / a[k] : t[k];
        d.albedo[k] = (float)turned;
        d.transmittance[k] = (float)(through < 1 - turned ? through : 1 - turned);
    }
    return scene_add_material(s, &d, err);
}

int scene_turn_leaves(scene *s, uint32_t sp, const char *label, const double c[3], double f, err_buf *err)
{
    uint32_t n = s->n_materials;
    int32_t *turned = malloc((n ? n : 1) * sizeof *turned); /* old material id → its copy, or -1; owned here */
    if (!turned) return err_nomem(err, "out of memory colouring the leaves of species '%s'", s->species[sp].name);
    for (uint32_t k = 0; k < n; k++) turned[k] = -1;
    const species *spc = &s->species[sp];
    int rc = 0;
    for (uint32_t v = 0; v < spc->n_variants && !rc; v++) {
        mesh *m = s->prototypes[spc->first_prototype + v].mesh;
        for (uint32_t t = 0; t < m->nt; t++) {
            uint32_t id = scene_triangle_material(s, m, t);
            if (id >= n || s->materials[id].bsdf != SYLVA_BSDF_LEAF) continue;
            if (turned[id] < 0 && (turned[id] = turned_material(s, id, spc->name, label, c, f, err)) < 0) {
                rc = -1;
                break;
            }
            m->mat[t] = turned[id];
        }
    }
    free(turned);
    return rc;
}

uint64_t scene_leaf_fall_key(const char *species_name, uint32_t v)
{
    return rng_combine(rng_combine(rng_hash_str("leaf fall"), rng_hash_str(species_name)), v);
}

/* The representative vertex of v's set (path halving). */
static uint32_t leaf_set(uint32_t *parent, uint32_t v)
{
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

int scene_drop_fallen_leaves(const scene *s, mesh *m, uint64_t key, double share, uint32_t *dropped,
                             err_buf *err)
{
    *dropped = 0;
    if (share <= 0 || !m->nt) return 0;
    /* parent: the vertices' sets joined by leaf triangles; first: each set's first leaf triangle */
    uint32_t *parent = malloc((size_t)m->nv * 2 * sizeof *parent); /* owned here */
    if (!parent) return err_nomem(err, "out of memory letting leaves fall from a %u-vertex mesh", m->nv);
    uint32_t *first = parent + m->nv;
    for (uint32_t v = 0; v < m->nv; v++) parent[v] = v, first[v] = UINT32_MAX;
    for (uint32_t t = 0; t < m->nt; t++) {
        if (s->materials[scene_triangle_material(s, m, t)].bsdf != SYLVA_BSDF_LEAF) continue;
        const uint32_t *c = m->tri + (size_t)t * 3;
        for (int k = 1; k < 3; k++) {
            uint32_t a = leaf_set(parent, c[0]), b = leaf_set(parent, c[k]);
            if (a != b) parent[a > b ? a : b] = a < b ? a : b; /* the smaller vertex leads the set */
        }
    }
    uint32_t kept = 0;
    for (uint32_t t = 0; t < m->nt; t++) {
        if (s->materials[scene_triangle_material(s, m, t)].bsdf == SYLVA_BSDF_LEAF) {
            uint32_t r = leaf_set(parent, m->tri[(size_t)t * 3]);
            if (first[r] == UINT32_MAX) first[r] = t;
            if (rng_u01f(rng_combine(key, first[r])) < share) continue;
        }
        keep_triangle(m, t, kept++);
    }
    free(parent);
    *dropped = m->nt - kept;
    m->nt = kept;
    return 0;
}

/* Species sp's leaves already down on a day when share of them has fallen. */
static int fall_species(scene *s, uint32_t sp, double share, err_buf *err)
{
    const species *spc = &s->species[sp];
    for (uint32_t v = 0; v < spc->n_variants; v++) {
        uint32_t dropped;
        if (scene_drop_fallen_leaves(s, s->prototypes[spc->first_prototype + v].mesh,
                                     scene_leaf_fall_key(spc->name, v), share, &dropped, err))
            return -1;
    }
    return 0;
}

int scene_apply_season(scene *s, uint32_t i, const phenology *p, uint32_t day, err_buf *err)
{
    const species *sp = &s->species[i];
    if (!phenology_in_leaf(p, day)) {
        for (uint32_t v = 0; v < sp->n_variants; v++) scene_drop_leaves(s, s->prototypes[sp->first_prototype + v].mesh);
        return 0;
    }
    double f = phenology_autumn_share(p, day);
    if (f > 0 && scene_turn_leaves(s, i, "autumn", p->autumn_color, f, err)) return -1;
    if (f > 0 && fall_species(s, i, phenology_fallen_share(p, day), err)) return -1;
    return 0;
}
