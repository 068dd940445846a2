/* planting_stock.c — the young plants of a planting plan: each stock's form at its year, grown
 * toward its species' model (planting_stock.h). */
#include "scene_build/planting_stock.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene_build/planting_growth.h"
#include "scene_build/stock_mesh.h"
#include "util/rng.h"

#define STOCK_MAX_LEAVES 15000u
#define STANDARD_CLEAR_STEM 1.8 /* metres: a standard's stem clear of branches (the trade's) */

/* The form of a stock at planting: its crown's reach (a share of the plant's height), its
 * lowest lateral's height, the spacing of its laterals and the share of them grown, their angle
 * from the vertical, and its leaves per lateral (per metre of stem for a whip). */
typedef struct stock_form {
    double reach, base, spacing, share, angle, leaves;
    int rounded;
} stock_form;

static const stock_form forms[] = {
    [STOCK_WHIP] = {.reach = 0.04, .base = 0.1, .spacing = 0.12, .share = 0, .angle = 55, .leaves = 30},
    [STOCK_FEATHERED] = {.reach = 0.13, .base = 0.12, .spacing = 0.11, .share = 0.75, .angle = 55, .leaves = 6},
    [STOCK_STANDARD] = {.reach = 0.17, .base = 0, .spacing = 0.15, .share = 0.8, .angle = 50, .leaves = 10, .rounded = 1},
};

/* What the species' model is at the plant's age, scaled to its height: its crown's reach (half
 * its mean width) and its leaves' area. */
typedef struct model_measure {
    double reach, leaf_area;
} model_measure;

static model_measure measure_model(const scene *s, uint32_t sp, double age_norm, double height)
{
    const prototype *pr = &s->prototypes[s->species[sp].first_prototype + scene_variant_for_age(s, sp, age_norm)];
    double scale = pr->height > 0 ? height / pr->height : 0, area = 0;
    float lo[3], hi[3];
    mesh_bounds(pr->mesh, lo, hi);
    const mesh *m = pr->mesh;
    for (uint32_t t = 0; t < m->nt; t++) {
        if (s->materials[scene_triangle_material(s, m, t)].bsdf != SYLVA_BSDF_LEAF) continue;
        const float *a = &m->pos[3 * m->tri[3 * t]], *b = &m->pos[3 * m->tri[3 * t + 1]], *c = &m->pos[3 * m->tri[3 * t + 2]];
        vec3 e1 = v3(b[0] - a[0], b[1] - a[1], b[2] - a[2]), e2 = v3(c[0] - a[0], c[1] - a[1], c[2] - a[2]);
        area += 0.5 * v3_len(v3_cross(e1, e2));
    }
    return (model_measure){.reach = 0.25 * scale * ((hi[0] - lo[0]) + (hi[1] - lo[1])), .leaf_area = scale * scale * area};
}

/* A material of the plan's guards and stakes, added once. */
static int32_t protection_material(scene *s, const char *name, float r, float g, float b, err_buf *err)
{
    int32_t m = scene_find_material(s, name);
    if (m >= 0) return m;
    sylva_material_desc d = {.size = sizeof d, .name = name, .bsdf = SYLVA_BSDF_LAMBERT, .albedo = {r, g, b},
                             .texture = -1};
    return scene_add_material(s, &d, err);
}

/* The shape of a young plant of feature f's stock of species sp at `years` after planting,
 * drawn at the height its stock's middle size has then; returns its normalised age then. */
static double shape_of(const scene *s, const planting_spec *plan, const planting_feature *f, uint32_t sp, double years,
                     const stock_leaf *leaf, stock_shape *sh)
{
    const stock_form *fm = &forms[f->stock];
    double F = plan->full_grown_age, mid = 0.5 * (f->stock_height[0] + f->stock_height[1]);
    double age = fmax(planting_age_for_height(s, sp, F, mid), 0) + years, h = planting_height_at(s, sp, F, age);
    double k = fmin(fmax(years / PLANTING_ESTABLISHMENT_YEARS, 0), 1);
    model_measure mm = measure_model(s, sp, fmax(1e-9, fmin(1.0, age / F)), h);
    double reach0 = fm->reach * h, base0 = f->stock == STOCK_STANDARD ? fmin(STANDARD_CLEAR_STEM, 0.65 * mid) : fm->base * h;
    double spacing = fm->spacing * (1 - 0.4 * k), share = fm->share + (1 - fm->share) * k;
    double stations = fmax(0, 0.94 * h - base0) / spacing;
    double leaves0 = f->stock == STOCK_WHIP ? fm->leaves * h : fm->leaves * stations * fm->share + 8;
    double leaves_model = leaf && leaf->area > 0 ? mm.leaf_area / leaf->area : 0;
    double leaves = leaves0 + (leaves_model - leaves0) * k;
    *sh = (stock_shape){.height = h, .stem_radius = h / 170, .crown_radius = fmax(reach0, reach0 + (mm.reach - reach0) * k),
                        .crown_base = f->stock == STOCK_STANDARD ? base0 : base0 + (0.05 * h - base0) * k,
                        .lateral_spacing = spacing, .lateral_share = share, .lateral_angle = fm->angle,
                        .rounded = fm->rounded, .leaves = (uint32_t)fmin(STOCK_MAX_LEAVES, fmax(0, leaves) + 0.5),
                        .leaf = leaf};
    if (years < PLANTING_GUARD_YEARS) {
        if (f->stock == STOCK_STANDARD) sh->stake_height = fmin(1.0, 0.4 * h);
        else sh->guard_height = fmin(0.6, 0.7 * h);
    }
    return fmax(1e-9, fmin(1.0, age / F));
}

/* The commonest material of the model's triangles that is no leaf (its bark). */
static int32_t bark_of(const scene *s, uint32_t sp)
{
    const mesh *m = s->prototypes[s->species[sp].first_prototype + s->species[sp].n_variants - 1].mesh;
    uint32_t best = 0, best_n = 0;
    for (uint32_t t = 0; t < m->nt; t += 1 + m->nt / 4096) { /* a sample of the triangles is enough */
        uint32_t id = scene_triangle_material(s, m, t), n = 0;
        if (s->materials[id].bsdf == SYLVA_BSDF_LEAF) continue;
        for (uint32_t u = 0; u < m->nt; u += 1 + m->nt / 4096) n += scene_triangle_material(s, m, u) == id;
        if (n > best_n) best = id, best_n = n;
    }
    return best_n ? (int32_t)best : s->default_material;
}

/* Plants of species place k of feature fi in the plan. */
static uint32_t plants_of(const planted_plant *plants, uint32_t n, const planting_feature *f, uint32_t fi, uint32_t k)
{
    uint32_t c = 0;
    for (uint32_t i = 0; i < n; i++) c += plants[i].feature == fi && plants[i].species == f->species[k];
    return c;
}

typedef struct young_ctx {
    scene *s;
    const planting_spec *plan;
    double years;
    int32_t guard, stake;
    err_buf *err;
} young_ctx;

/* The individuals of feature fi's species place k (species sp) as prototypes of young species ysp. */
static int build_individuals(young_ctx *c, uint32_t fi, uint32_t k, uint32_t sp, uint32_t ysp, uint32_t count,
                             const stock_leaf *leaf, planting_young *y)
{
    scene *s = c->s;
    stock_shape sh;
    double age = shape_of(s, c->plan, &c->plan->features[fi], sp, c->years, leaf, &sh);
    sh.bark = bark_of(s, sp), sh.guard = c->guard, sh.stake = c->stake;
    size_t slot = (size_t)fi * PLANTING_MAX_SPECIES + k;
    y->first[slot] = s->n_prototypes, y->count[slot] = count, y->species[slot] = sp;
    for (uint32_t i = 0; i < count; i++) {
        uint64_t seed = rng_combine(rng_combine(c->plan->seed, fi), (uint64_t)k * 64 + i);
        mesh *m = stock_mesh_new(&sh, seed, c->err); /* the scene's once added */
        if (!m) return -1;
        if (scene_add_prototype(s, ysp, s->species[ysp].n_variants, age, sh.height, m, c->err) < 0) return -1;
        s->species[ysp].n_variants++;
    }
    return 0;
}

/* The young species of model species sp and its prototypes, feature by feature. */
static int build_species(young_ctx *c, uint32_t sp, const planted_plant *plants, uint32_t n, planting_young *y)
{
    scene *s = c->s;
    int32_t ysp = -1;
    stock_leaf leaf = {0}; /* owned here */
    int rc = 0;
    for (uint32_t fi = 0; fi < c->plan->n_features && !rc; fi++) {
        const planting_feature *f = &c->plan->features[fi];
        for (uint32_t k = 0; k < f->n_species && f->kind != PLANTING_FELLING && !rc; k++) {
            uint32_t count = f->species[k] == sp ? plants_of(plants, n, f, fi, k) : 0;
            for (uint32_t j = 0; j < k && count; j++) count = f->species[j] == sp ? 0 : count; /* built at j */
            if (!count) continue;
            if (ysp < 0) {
                const species *model = &s->species[sp];
                rc = stock_leaf_of(s, s->prototypes[model->first_prototype + model->n_variants - 1].mesh, &leaf, c->err) < 0;
                if (!rc && (ysp = scene_add_species(s, s->species[sp].name, c->err)) < 0) rc = 1;
                if (!rc) s->species[ysp].young_stock_of = sp + 1;
            }
            if (!rc) rc = build_individuals(c, fi, k, sp, (uint32_t)ysp, count < PLANTING_STOCK_INDIVIDUALS ? count : PLANTING_STOCK_INDIVIDUALS,
                                            leaf.nt ? &leaf : NULL, y);
        }
    }
    stock_leaf_release(&leaf);
    return rc ? -1 : 0;
}

int planting_young_build(scene *s, const planting_spec *plan, const planted_plant *plants, uint32_t n, double years,
                         planting_young *y, err_buf *err)
{
    memset(y, 0, sizeof *y);
    if (!(years < PLANTING_ESTABLISHMENT_YEARS) || !plan->n_features) return 0;
    size_t slots = (size_t)plan->n_features * PLANTING_MAX_SPECIES;
    y->first = malloc(slots * sizeof *y->first), y->count = calloc(slots, sizeof *y->count); /* y's */
    y->species = calloc(slots, sizeof *y->species);                                           /* y's */
    if (!y->first || !y->count || !y->species) {
        planting_young_release(y);
        return err_nomem(err, "out of memory for the young plants of the planting plan");
    }
    y->n_features = plan->n_features;
    for (size_t k = 0; k < slots; k++) y->first[k] = UINT32_MAX;
    young_ctx c = {.s = s, .plan = plan, .years = years, .err = err};
    c.guard = protection_material(s, "planting.spiral_guard", 0.55f, 0.6f, 0.52f, err);
    c.stake = c.guard < 0 ? -1 : protection_material(s, "planting.stake", 0.3f, 0.24f, 0.17f, err);
    int rc = c.stake < 0 ? -1 : 0;
    uint32_t n_model = s->n_species; /* the young species are added after every model species */
    for (uint32_t sp = 0; sp < n_model && !rc; sp++)
        if (!s->species[sp].young_stock_of && s->species[sp].n_variants) rc = build_species(&c, sp, plants, n, y);
    if (rc) planting_young_release(y);
    return rc;
}

int64_t planting_young_prototype(const planting_young *y, const planted_plant *p, uint32_t id)
{
    if (!y->first || p->feature >= y->n_features) return -1;
    for (uint32_t k = 0; k < PLANTING_MAX_SPECIES; k++) {
        size_t slot = (size_t)p->feature * PLANTING_MAX_SPECIES + k;
        if (y->first[slot] != UINT32_MAX && y->species[slot] == p->species)
            return (int64_t)y->first[slot] + (int64_t)(rng_mix64(id) % y->count[slot]);
    }
    return -1;
}

void planting_young_release(planting_young *y)
{
    free(y->first), free(y->count), free(y->species);
    memset(y, 0, sizeof *y);
}
