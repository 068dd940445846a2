/* scene_communities.c — the land cover's plant communities placed without simulation
 * (scene_communities.h). */
#include "scene_build/scene_communities.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "scene_build/plant_scale.h"
#include "site/landcover.h"
#include "util/gradient_noise.h"
#include "util/rng.h"

/* The most plants the communities may place, so that a map of a whole county at forest density
 * is refused before it fills the memory (about 100 bytes a plant in the scene and its BVH). */
#define COMMUNITY_MAX_PLANTS 8000000.0
/* The most nodes of the planting grid (26 bytes each while the map is read on it). */
#define COMMUNITY_MAX_NODES 50000000.0
/* The most node lookups the edge band may cost (each cell looks at the nodes within plant_edge
 * of it): about ten seconds' work. */
#define COMMUNITY_MAX_EDGE_LOOKUPS 5e9

typedef struct planting {
    scene *s;
    const scene_file *sf;
    const landcover_spec *spec;
    const land_cover *lc;       /* the map on the planting grid; owned by the caller */
    int32_t *community;         /* per class of lc: the community's index, or -1; owned by the caller */
    uint64_t *placed;           /* per community and species: plants placed; owned by the caller */
    uint64_t outside;           /* plants that fell outside the terrain */
    uint64_t seed;
} planting;

int32_t landcover_community_of(const landcover_spec *spec, const land_class *c)
{
    int32_t by_kind = -1, by_broad = -1;
    for (uint32_t k = 0; k < spec->n_communities; k++) {
        const landcover_community *m = &spec->communities[k];
        if (m->kind < 0 && m->code == c->code) return (int32_t)k;
        if (m->kind == (int)c->kind) by_kind = (int32_t)k;
        if (m->kind >= 0 && m->kind != (int)c->kind && m->kind == (int)land_kind_broad(c->kind)) by_broad = (int32_t)k;
    }
    return by_kind >= 0 ? by_kind : by_broad;
}

int community_species_grown(const scene_file *sf, uint32_t sp)
{
    return sf->ecology.plugin && sp < sf->n_species && sf->species[sp].ecology;
}

/* The grid the map is read on for planting: nodes plant_spacing apart over the plant area (or
 * the surveyed ground), each cell between four of them planted as one. */
static landcover_grid planting_grid(const scene *s, const scene_file *sf)
{
    const landcover_spec *spec = &sf->landcover;
    const sylva_heightfield *hf = s->surveyed;
    double west = hf->x0, south = hf->y0, east = hf->x0 + (hf->nx - 1) * hf->dx, north = hf->y0 + (hf->ny - 1) * hf->dy;
    if (spec->has_plant_area) {
        west = fmax(west, spec->plant_area[0] - sf->site.origin[0]);
        south = fmax(south, spec->plant_area[1] - sf->site.origin[1]);
        east = fmin(east, spec->plant_area[2] - sf->site.origin[0]);
        north = fmin(north, spec->plant_area[3] - sf->site.origin[1]);
    }
    double d = spec->plant_spacing;
    landcover_grid g = {sf->site.crs_wkt, {sf->site.origin[0], sf->site.origin[1]}, 0, 0, west, south, d, d};
    double nx = floor((east - west) / d) + 1, ny = floor((north - south) / d) + 1;
    if (nx >= 2 && ny >= 2 && nx * ny <= COMMUNITY_MAX_NODES) g.nx = (uint32_t)nx, g.ny = (uint32_t)ny;
    return g;
}

/* The plants the communities would place on the grid: their expected number. */
static double expected_plants(const planting *p)
{
    const land_cover *lc = p->lc;
    double cell_ha = lc->dx * lc->dy / 1e4, n = 0; /* counted by node: a bound on the cells' */
    for (uint32_t c = 0; c < lc->n_classes; c++)
        if (p->community[c] >= 0) n += (double)lc->classes[c].nodes * p->spec->communities[p->community[c]].density * cell_ha;
    return n;
}

/* One plant of community m at (x, y), its species, height and turn drawn from r. */
static int plant_one(planting *p, uint32_t m, double x, double y, sylva_rng *r, err_buf *err)
{
    const landcover_community *c = &p->spec->communities[m];
    double pick = rng_next_double(r), h = c->height[0] + rng_next_double(r) * (c->height[1] - c->height[0]);
    double turn = 360.0 * rng_next_double(r), z;
    uint32_t k = 0;
    for (double acc = c->share[0]; k + 1 < c->n_species && pick >= acc; acc += c->share[++k]) {}
    uint32_t sp = c->species[k];
    if (community_species_grown(p->sf, sp)) return 0; /* the ecology grows it there */
    if (scene_terrain_height(p->s, x, y, &z)) return p->outside++, 0;
    const species *spc = &p->s->species[sp];
    if (!spc->n_variants) return err_set(err, "species '%s' has no model", spc->name);
    uint32_t proto = spc->first_prototype + scene_variant_nearest_height(p->s, sp, h);
    const prototype *pr = &p->s->prototypes[proto];
    if (!(pr->height > 0)) return err_set(err, "the model of species '%s' has no height to scale to %g m", spc->name, h);
    double sv, sh;
    plant_scales(pr, h, 0, &sv, &sh);
    xform3x4 xf = xf_trs(v3((float)x, (float)y, (float)z), v3(0, 0, (float)turn), v3((float)sh, (float)sh, (float)sv));
    if (scene_add_instance(p->s, proto, &xf, err) < 0) return -1;
    p->placed[(size_t)m * COMMUNITY_MAX_SPECIES + k]++;
    return 0;
}

/* The community of node (i, j), or -1. */
static int32_t node_community(const planting *p, uint32_t i, uint32_t j)
{
    uint16_t cls = p->lc->node_class[(size_t)j * p->lc->nx + i];
    return cls == LAND_COVER_NONE ? -1 : p->community[cls];
}

/* The share of a community's density a cell keeps near the community's edge (plant_edge e):
 * with d the distance from the cell's south-west node to the nearest node of another class (or
 * none) within e, and n a smooth noise in [-1, 1] of wavelength 4e, S(d / e + 0.3 n), S the
 * smoothstep on [0, 1], so a wood thins out toward its edge over a band that wanders by up to a
 * third of its width. The grid's own edge is no edge. 1 away from every edge or for e = 0. */
static double edge_share(const planting *p, uint32_t i, uint32_t j, int32_t m)
{
    const land_cover *lc = p->lc;
    double e = p->spec->plant_edge;
    if (!(e > 0)) return 1;
    int64_t ri = (int64_t)ceil(e / lc->dx), rj = (int64_t)ceil(e / lc->dy);
    double best = INFINITY;
    for (int64_t b = -rj; b <= rj; b++)
        for (int64_t a = -ri; a <= ri; a++) {
            int64_t x = (int64_t)i + a, y = (int64_t)j + b;
            if (x < 0 || y < 0 || x >= lc->nx || y >= lc->ny || node_community(p, (uint32_t)x, (uint32_t)y) == m) continue;
            best = fmin(best, hypot(a * lc->dx, b * lc->dy));
        }
    if (!(best <= e)) return 1;
    const noise_fbm wander = {.wavelength = 4 * e, .octaves = 2, .gain = 0.5f, .seed = 0xed6eu};
    double t = best / e + 0.3 * noise_fbm2(&wander, lc->x0 + i * lc->dx, lc->y0 + j * lc->dy, 0, NULL);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return t * t * (3 - 2 * t);
}

/* The plants of the cell between nodes (i, j) and (i + 1, j + 1), when its four corners share a
 * community: the whole part of the community's expected count per cell (thinned near its edge),
 * and one more with the chance of its fraction, each at a uniform point of the cell. A map's class boundary is a
 * straight line across such a cell, and each side of it holds a corner, so no plant stands on
 * the far side of a boundary; a band up to a cell wide along each boundary stays bare. */
static int plant_cell(planting *p, uint32_t i, uint32_t j, err_buf *err)
{
    const land_cover *lc = p->lc;
    int32_t m = node_community(p, i, j);
    if (m < 0 || node_community(p, i + 1, j) != m || node_community(p, i, j + 1) != m ||
        node_community(p, i + 1, j + 1) != m)
        return 0;
    sylva_rng r;
    rng_stream(&r, p->seed, "landcover community", (uint64_t)j * lc->nx + i);
    double expected = p->spec->communities[m].density * lc->dx * lc->dy / 1e4 * edge_share(p, i, j, m);
    uint64_t n = (uint64_t)expected + (rng_next_double(&r) < expected - floor(expected));
    double x0 = lc->x0 + i * lc->dx, y0 = lc->y0 + j * lc->dy;
    for (uint64_t k = 0; k < n; k++) {
        double x = x0 + rng_next_double(&r) * lc->dx, y = y0 + rng_next_double(&r) * lc->dy;
        if (plant_one(p, (uint32_t)m, x, y, &r, err)) return -1;
    }
    return 0;
}

/* The line the build prints: plants per community and species, and that they were not grown. */
static void summary(const planting *p, const scene_file *sf, const landcover_grid *g)
{
    uint64_t total = 0;
    for (uint32_t k = 0; k < p->spec->n_communities * COMMUNITY_MAX_SPECIES; k++) total += p->placed[k];
    fprintf(stderr, "sylva: landcover: %llu plants placed by community over %.1f km2, without simulation (the "
            "densities and heights the scene gives):", (unsigned long long)total, (g->nx - 1) * g->dx * (g->ny - 1) * g->dy / 1e6);
    for (uint32_t m = 0; m < p->spec->n_communities; m++) {
        const landcover_community *c = &p->spec->communities[m];
        if (c->kind >= 0) fprintf(stderr, "%s %s", m ? ";" : "", land_kind_names[c->kind]);
        else fprintf(stderr, "%s class %lld", m ? ";" : "", (long long)c->code);
        for (uint32_t k = 0; k < c->n_species; k++)
            if (community_species_grown(sf, c->species[k]))
                fprintf(stderr, "%s %s grown by the ecology", k ? "," : "", sf->species[c->species[k]].name);
            else
                fprintf(stderr, "%s %s %llu", k ? "," : "", sf->species[c->species[k]].name,
                        (unsigned long long)p->placed[(size_t)m * COMMUNITY_MAX_SPECIES + k]);
    }
    if (p->outside) fprintf(stderr, "; %llu off the terrain left out", (unsigned long long)p->outside);
    fputc('\n', stderr);
}

/* Reads the map onto the planting grid, checks the count and plants every node. */
static int plant_all(planting *p, const scene_file *sf, const landcover_grid *g, int quiet, err_buf *err)
{
    for (uint32_t c = 0; c < p->lc->n_classes; c++) p->community[c] = landcover_community_of(p->spec, &p->lc->classes[c]);
    double reach = (2 * ceil(p->spec->plant_edge / g->dx) + 1) * (2 * ceil(p->spec->plant_edge / g->dy) + 1);
    if (p->spec->plant_edge > 0 && (double)g->nx * g->ny * reach > COMMUNITY_MAX_EDGE_LOOKUPS)
        return err_at(err, ERR_INPUT, sf->path, p->spec->line, p->spec->column,
                      "landcover: a plant_edge of %g m on a grid of %g m over %u x %u nodes looks at %.3g nodes, more "
                      "than the %.0f a scene takes; give a narrower plant_edge, a larger plant_spacing or a smaller "
                      "plant_area", p->spec->plant_edge, g->dx, g->nx, g->ny, (double)g->nx * g->ny * reach,
                      COMMUNITY_MAX_EDGE_LOOKUPS);
    double expected = expected_plants(p);
    if (expected > COMMUNITY_MAX_PLANTS)
        return err_at(err, ERR_INPUT, sf->path, p->spec->communities[0].line, p->spec->communities[0].column,
                      "the communities would place about %.0f plants over %.1f km2, more than the %.0f a scene takes; "
                      "give a smaller plant_area (the land round the development and the views) or lower densities",
                      expected, (g->nx - 1) * g->dx * (g->ny - 1) * g->dy / 1e6, COMMUNITY_MAX_PLANTS);
    for (uint32_t j = 0; j + 1 < p->lc->ny; j++)
        for (uint32_t i = 0; i + 1 < p->lc->nx; i++)
            if (plant_cell(p, i, j, err))
                return err_locate(err, sf->path, p->spec->line, p->spec->column);
    if (!quiet) summary(p, sf, g);
    return 0;
}

int scene_build_communities(scene *s, const scene_file *sf, int quiet, err_buf *err)
{
    const landcover_spec *spec = &sf->landcover;
    if (!spec->given || !spec->n_communities || !s->surveyed) return 0;
    landcover_grid g = planting_grid(s, sf);
    if (!g.nx && spec->has_plant_area)
        return err_at(err, ERR_INPUT, sf->path, spec->line, spec->column,
                      "landcover: the plant_area [%g, %g, %g, %g] holds no cell of %g m on the terrain, or more "
                      "than %.0f; give an area of the site, at most that many cells", spec->plant_area[0],
                      spec->plant_area[1], spec->plant_area[2], spec->plant_area[3], spec->plant_spacing,
                      COMMUNITY_MAX_NODES);
    if (!g.nx)
        return err_at(err, ERR_INPUT, sf->path, spec->line, spec->column,
                      "landcover: planting the whole terrain on a grid of %g m takes more than %.0f cells (or none); "
                      "give plant_area: [west, south, east, north], the land round the development and the views, "
                      "or a larger plant_spacing", spec->plant_spacing, COMMUNITY_MAX_NODES);
    land_cover *lc = landcover_read(&spec->source, &g, NULL, NULL, err); /* owned here */
    if (!lc) {
        err_default(err, ERR_INPUT);
        return err->status == ERR_NOMEM ? -1 : err_locate(err, sf->path, spec->line, spec->column);
    }
    planting p = {s, sf, spec, lc, malloc(lc->n_classes * sizeof *p.community), /* owned here */
                  calloc((size_t)spec->n_communities * COMMUNITY_MAX_SPECIES, sizeof *p.placed), 0, s->image.seed};
    int rc = !p.community || !p.placed ? err_nomem(err, "out of memory for the communities")
                                       : plant_all(&p, sf, &g, quiet, err);
    free(p.community), free(p.placed);
    land_cover_free(lc);
    return rc;
}
