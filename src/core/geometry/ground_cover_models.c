/* ground_cover_models.c — procedural grass tufts and herbs (see ground_cover_models.h). Every
 * part is one strip: a centre line that leans away from the vertical more and more along its
 * length (a bending blade), swept sideways by a width that follows a profile. */
#include "geometry/ground_cover_models.h"

#include <math.h>

#include "geometry/ground_cover.h"
#include "season/phenology.h"
#include "util/rng.h"

#define STRIP_SEGMENTS 5
#define STRIP_MAX_VERTICES (2 * STRIP_SEGMENTS + 2) /* a stem keeps its width to the top */
#define STRIP_MAX_TRIANGLES (2 * STRIP_SEGMENTS)

typedef enum strip_profile {
    STRIP_BLADE, /* widest at the base, tapering to a point at the tip */
    STRIP_LEAF,  /* narrow at the base, widest a third of the way, pointed at the tip */
    STRIP_STEM   /* the same width all along */
} strip_profile;

/* One strip: base point, azimuth of its lean, lean from the vertical at its base and tip
 * (radians), length and widest width (metres). */
typedef struct strip {
    double base[3];
    double azimuth, lean0, lean1;
    double length, width;
    strip_profile profile;
    int32_t material;
} strip;

static double strip_width(const strip *st, double t)
{
    switch (st->profile) {
    case STRIP_BLADE: return st->width * pow(1.0 - t, 0.6);
    case STRIP_LEAF: return st->width * (0.25 + 0.75 * sin(M_PI * pow(t, 0.7)));
    case STRIP_STEM: return st->width;
    }
    return st->width;
}

/* Appends st to m: a pair of vertices across the centre line at each of its STRIP_SEGMENTS + 1
 * stations, but a single vertex at the tip where the blade and leaf profiles come to a point. */
static int strip_append(mesh *m, const strip *st, err_buf *err)
{
    float pos[3 * STRIP_MAX_VERTICES], nrm[3 * STRIP_MAX_VERTICES], uv[2 * STRIP_MAX_VERTICES];
    uint32_t tri[3 * STRIP_MAX_TRIANGLES];
    double ca = cos(st->azimuth), sa = sin(st->azimuth);
    double side[3] = {-sa, ca, 0};
    double p[3] = {st->base[0], st->base[1], st->base[2]};
    double step = st->length / STRIP_SEGMENTS;
    uint32_t nv = 0;
    for (uint32_t k = 0; k <= STRIP_SEGMENTS; k++) {
        double t = (double)k / STRIP_SEGMENTS;
        double lean = st->lean0 + (st->lean1 - st->lean0) * t;
        double tan_dir[3] = {sin(lean) * ca, sin(lean) * sa, cos(lean)};
        /* the face normal: the tangent crossed with the sideways direction */
        double n[3] = {tan_dir[1] * side[2] - tan_dir[2] * side[1], tan_dir[2] * side[0] - tan_dir[0] * side[2],
                       tan_dir[0] * side[1] - tan_dir[1] * side[0]};
        int tip = k == STRIP_SEGMENTS && st->profile != STRIP_STEM;
        double hw = tip ? 0.0 : 0.5 * strip_width(st, t);
        for (int s = tip ? 0 : -1; s <= (tip ? 0 : 1); s += 2) {
            for (int c = 0; c < 3; c++) pos[3 * nv + c] = (float)(p[c] + s * hw * side[c]), nrm[3 * nv + c] = (float)n[c];
            uv[2 * nv] = tip ? 0.5f : (float)(s + 1) * 0.5f, uv[2 * nv + 1] = (float)t;
            nv++;
        }
        for (int c = 0; c < 3; c++) p[c] += step * tan_dir[c];
    }
    uint32_t nt = 0;
    for (uint32_t k = 0; k < STRIP_SEGMENTS; k++) {
        uint32_t a = 2 * k, b = a + 1, c = a + 2, d = a + 3;
        tri[3 * nt] = a, tri[3 * nt + 1] = b, tri[3 * nt + 2] = c, nt++;
        if (d < nv) tri[3 * nt] = b, tri[3 * nt + 1] = d, tri[3 * nt + 2] = c, nt++;
    }
    return mesh_append(m, pos, nrm, uv, nv, tri, NULL, st->material, nt, err);
}

static double uniform(sylva_rng *r, double lo, double hi) { return lo + (hi - lo) * rng_next_double(r); }

/* A tuft: `blades` blades from a clump of radius 3 cm, lengths in [len_lo, len_hi], a share
 * `dry_share` of them in the dry material. */
static int tuft(mesh *m, sylva_rng *r, uint32_t blades, double len_lo, double len_hi, double dry_share,
                int32_t green, int32_t dry, err_buf *err)
{
    for (uint32_t b = 0; b < blades; b++) {
        double rr = 0.03 * sqrt(rng_next_double(r)), ra = uniform(r, 0, 2 * M_PI);
        strip st = {.base = {rr * cos(ra), rr * sin(ra), 0}, .azimuth = uniform(r, 0, 2 * M_PI),
                    .lean0 = uniform(r, 0.03, 0.4), .length = uniform(r, len_lo, len_hi),
                    .width = uniform(r, 0.003, 0.006), .profile = STRIP_BLADE};
        st.lean1 = st.lean0 + uniform(r, 0.2, 1.1);
        st.material = rng_next_double(r) < dry_share ? dry : green;
        if (strip_append(m, &st, err)) return -1;
    }
    return 0;
}

/* A flower head at `top`: `petals` petals of length len and width wid leaning by `lean`, round a
 * centre of small flat petals. */
static int flower(mesh *m, sylva_rng *r, const double top[3], uint32_t petals, double len, double wid, double lean,
                  int32_t petal, int32_t centre, err_buf *err)
{
    double turn = uniform(r, 0, 2 * M_PI);
    for (uint32_t k = 0; k < petals; k++) {
        strip st = {.base = {top[0], top[1], top[2]}, .azimuth = turn + 2 * M_PI * k / petals,
                    .lean0 = lean, .lean1 = lean + uniform(r, 0.0, 0.3), .length = len * uniform(r, 0.85, 1.1),
                    .width = wid, .profile = STRIP_LEAF, .material = petal};
        if (strip_append(m, &st, err)) return -1;
    }
    for (uint32_t k = 0; k < 6; k++) {
        strip st = {.base = {top[0], top[1], top[2] + 0.002}, .azimuth = turn + M_PI * k / 3, .lean0 = 1.3,
                    .lean1 = 1.4, .length = 0.3 * len, .width = 0.5 * wid, .profile = STRIP_LEAF,
                    .material = centre};
        if (strip_append(m, &st, err)) return -1;
    }
    return 0;
}

/* A forb: a rosette of leaves, 1 to 3 stems with two leaves each and a flower head. */
static int herb(mesh *m, sylva_rng *r, uint32_t petals, double petal_len, double petal_wid, double petal_lean,
                int32_t leaf, int32_t petal, int32_t centre, double *height, err_buf *err)
{
    uint32_t rosette = 5 + (uint32_t)(rng_next_double(r) * 4);
    for (uint32_t k = 0; k < rosette; k++) {
        strip st = {.azimuth = 2 * M_PI * (k + uniform(r, -0.2, 0.2)) / rosette, .lean0 = uniform(r, 0.6, 1.0),
                    .length = uniform(r, 0.07, 0.13), .width = uniform(r, 0.02, 0.035), .profile = STRIP_LEAF,
                    .material = leaf};
        st.lean1 = st.lean0 + uniform(r, 0.3, 0.6);
        if (strip_append(m, &st, err)) return -1;
    }
    uint32_t stems = 1 + (uint32_t)(rng_next_double(r) * 3);
    *height = 0;
    for (uint32_t k = 0; k < stems; k++) {
        double az = uniform(r, 0, 2 * M_PI), lean = uniform(r, 0.0, 0.25), len = uniform(r, 0.2, 0.4);
        strip stem = {.base = {0.01 * cos(az), 0.01 * sin(az), 0}, .azimuth = az, .lean0 = lean,
                      .lean1 = lean + uniform(r, 0.0, 0.15), .length = len, .width = 0.003, .profile = STRIP_STEM,
                      .material = leaf};
        if (strip_append(m, &stem, err)) return -1;
        /* the stem's centre line again, to hang its leaves and flower on */
        double p[3] = {stem.base[0], stem.base[1], 0};
        for (uint32_t s = 0; s < STRIP_SEGMENTS; s++) {
            double t = (s + 0.5) / STRIP_SEGMENTS, ln = stem.lean0 + (stem.lean1 - stem.lean0) * t;
            double step = len / STRIP_SEGMENTS;
            p[0] += step * sin(ln) * cos(az), p[1] += step * sin(ln) * sin(az), p[2] += step * cos(ln);
            if (s == 1 || s == 3) {
                strip sl = {.base = {p[0], p[1], p[2]}, .azimuth = az + (s == 1 ? 1.6 : -1.6) + uniform(r, -0.4, 0.4),
                            .lean0 = 0.8, .lean1 = 1.3, .length = uniform(r, 0.04, 0.07),
                            .width = uniform(r, 0.01, 0.018), .profile = STRIP_LEAF, .material = leaf};
                if (strip_append(m, &sl, err)) return -1;
            }
        }
        if (flower(m, r, p, petals, petal_len, petal_wid, petal_lean, petal, centre, err)) return -1;
        if (p[2] > *height) *height = p[2];
    }
    return 0;
}

static int32_t leaf_material(scene *s, const char *name, float r, float g, float b, float tr, float tg, float tb,
                             err_buf *err)
{
    sylva_material_desc d = {.size = sizeof d, .name = name, .bsdf = SYLVA_BSDF_LEAF, .albedo = {r, g, b},
                             .transmittance = {tr, tg, tb}, .texture = -1};
    return scene_add_material(s, &d, err);
}

/* A species of ground cover (no canopy, no crown proxy): its index, or -1 with err set. */
static int32_t cover_species(scene *s, const char *name, err_buf *err)
{
    int32_t sp = scene_add_species(s, name, err);
    if (sp >= 0) s->species[sp].ground_cover = 1;
    return sp;
}

/* The blade colours of a temperate meadow's fresh and cured grass, reflectance then
 * transmittance, coloured after the ground the tufts stand on: each channel scaled by the
 * ground's grass (dry grass) albedo over the temperate ground's, so a temperate ground keeps
 * these colours to the bit and a biome's grass tints its blades (docs/models/ground.md). */
static void blade_colours(const scene *s, float fresh[6], float cured[6])
{
    static const float temperate_fresh[6] = {0.075f, 0.13f, 0.035f, 0.05f, 0.12f, 0.02f},
                       temperate_cured[6] = {0.30f, 0.25f, 0.13f, 0.14f, 0.11f, 0.05f},
                       temperate_grass[3] = {0.07f, 0.10f, 0.04f}, temperate_dry[3] = {0.30f, 0.26f, 0.12f};
    const sylva_heightfield *hf = s->terrain;
    const int ruled = hf && SYLVA_HAS_FIELD(hf, sylva_heightfield, humidity) && hf->has_ground_rules;
    for (int k = 0; k < 3; k++) {
        double g = ruled ? hf->ground.grass_albedo[k] / temperate_grass[k] : 1.0;
        double d = ruled ? hf->ground.dry_grass_albedo[k] / temperate_dry[k] : 1.0;
        /* a leaf reflects and transmits at most what it receives */
        double gs = fmin(g, 0.98 / (temperate_fresh[k] + temperate_fresh[k + 3]));
        double ds = fmin(d, 0.98 / (temperate_cured[k] + temperate_cured[k + 3]));
        fresh[k] = (float)(temperate_fresh[k] * gs), fresh[k + 3] = (float)(temperate_fresh[k + 3] * gs);
        cured[k] = (float)(temperate_cured[k] * ds), cured[k + 3] = (float)(temperate_cured[k + 3] * ds);
    }
}

int ground_cover_models_add(scene *s, uint64_t seed, ground_cover_models *out, err_buf *err)
{
    /* Linear reflectance and transmittance of fresh and cured grass blades (the ground's), herb
     * leaves and the petals of white and yellow meadow flowers (docs/rendering.md, Ground
     * cover). */
    float fresh[6], cured[6];
    blade_colours(s, fresh, cured);
    /* out of the growing season the green blades turn toward cured grass as the meadow's ground
     * does, and the herbs stand without flowers */
    double dormancy = meadow_dormancy(s->season_day);
    float t = (float)(GROUND_MEADOW_REST_SHARE * dormancy), g[6];
    for (int k = 0; k < 6; k++) g[k] = fresh[k] + t * (cured[k] - fresh[k]);
    int32_t green = leaf_material(s, "ground cover grass", g[0], g[1], g[2], g[3], g[4], g[5], err);
    int32_t dry = leaf_material(s, "ground cover dry grass", cured[0], cured[1], cured[2], cured[3], cured[4], cured[5], err);
    int32_t leaf = leaf_material(s, "ground cover herb leaf", 0.06f, 0.12f, 0.04f, 0.04f, 0.10f, 0.02f, err);
    int32_t white = leaf_material(s, "ground cover white petal", 0.70f, 0.70f, 0.62f, 0.20f, 0.20f, 0.17f, err);
    int32_t yellow = leaf_material(s, "ground cover yellow petal", 0.62f, 0.45f, 0.03f, 0.25f, 0.15f, 0.01f, err);
    int32_t centre = leaf_material(s, "ground cover flower centre", 0.45f, 0.32f, 0.03f, 0.10f, 0.07f, 0.01f, err);
    if (green < 0 || dry < 0 || leaf < 0 || white < 0 || yellow < 0 || centre < 0) return -1;
    if (dormancy >= 0.5) white = yellow = centre = leaf;

    static const struct {
        uint32_t blades;
        double len_lo, len_hi, dry_share;
    } grass[GROUND_COVER_GRASS_VARIANTS] = {{28, 0.08, 0.22, 0.0}, {40, 0.18, 0.45, 0.05}, {34, 0.12, 0.35, 0.35}};
    int32_t sp = cover_species(s, "ground cover grass", err);
    if (sp < 0) return -1;
    out->grass_first = s->n_prototypes;
    for (uint32_t v = 0; v < GROUND_COVER_GRASS_VARIANTS; v++) {
        sylva_rng r;
        rng_stream(&r, seed, "ground cover grass", v);
        mesh *m = mesh_new();
        if (!m) return err_nomem(err, "out of memory building the ground cover");
        if (tuft(m, &r, grass[v].blades, grass[v].len_lo, grass[v].len_hi, grass[v].dry_share, green, dry, err)) {
            mesh_free(m);
            return -1;
        }
        if (scene_add_prototype(s, (uint32_t)sp, v, 1.0, grass[v].len_hi, m, err) < 0) return -1;
        s->species[sp].n_variants++;
    }
    if ((sp = cover_species(s, "ground cover herb", err)) < 0) return -1;
    out->herb_first = s->n_prototypes;
    for (uint32_t v = 0; v < GROUND_COVER_HERB_VARIANTS; v++) {
        sylva_rng r;
        rng_stream(&r, seed, "ground cover herb", v);
        mesh *m = mesh_new();
        double h = 0;
        if (!m) return err_nomem(err, "out of memory building the ground cover");
        /* an ox-eye daisy's ray of narrow white petals; a buttercup's five broad cupped ones */
        int rc = v == 0 ? herb(m, &r, 16, 0.016, 0.004, 1.45, leaf, white, centre, &h, err)
                        : herb(m, &r, 5, 0.009, 0.008, 0.9, leaf, yellow, yellow, &h, err);
        if (rc) {
            mesh_free(m);
            return -1;
        }
        if (scene_add_prototype(s, (uint32_t)sp, v, 1.0, h, m, err) < 0) return -1;
        s->species[sp].n_variants++;
    }
    return 0;
}
