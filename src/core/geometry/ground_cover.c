/* ground_cover.c — continuous ground-cover weights from slope, height, humidity, water and
 * canopy (see ground_cover.h; the rules in docs/models/ground.md). */
#include "geometry/ground_cover.h"

#include <math.h>
#include <stdlib.h>

#include "scene/heightfield.h"
#include "season/phenology.h"
#include "util/gradient_noise.h"
#include "util/rng.h"

#define CANOPY_MAX_CELLS 2048u     /* along each side of the canopy raster */
#define CANOPY_MIN_CELL 0.5        /* metres */
#define CROWN_REACH 1.3            /* litter reaches this many crown radii from the stem */
#define CROWN_FULL 0.6             /* and is full cover within this many */
#define CROWN_LOW_HEIGHT 1.0       /* metres: a plant this low or lower leaves no litter */
#define CROWN_FULL_HEIGHT 10.0     /* metres: a plant this tall or taller shades fully */

struct ground_cover_map {
    const sylva_heightfield *hf;   /* the scene's; borrowed */
    sylva_ground_rules rules;
    double band;                   /* metres: half-width of the snow and scree lines' transition */
    double slope_step;             /* metres: the finite-difference step of the slope */
    float *canopy;                 /* cnx * cny crown cover in [0, 1], row 0 south; owned; or NULL */
    uint32_t cnx, cny;
    double cx0, cy0, cell;         /* centre of canopy cell (0, 0), and the cell size */
    snow_settings snow;            /* the scene's snow lying on the ground (off unless asked) */
    double snow_edge;              /* drift noise below which snow lies: its cover-quantile */
    float rest;                    /* how far the meadow has turned toward cured grass for its season */
    const land_cover *land;        /* the scene's land cover, or NULL; borrowed */
};

/* Boundary noise: where an edge between two kinds wanders (tens of metres), where patches lie
 * (metres to tens of metres), where bare soil shows through the turf. */
static const noise_fbm wander = {.wavelength = 60.0, .octaves = 5, .gain = 0.5f, .seed = 0x51u};
static const noise_fbm patch = {.wavelength = 18.0, .octaves = 4, .gain = 0.5f, .seed = 0x7au};
static const noise_fbm bare = {.wavelength = 35.0, .octaves = 4, .gain = 0.55f, .seed = 0xb3u};
/* Where lying snow leaves the ground bare when it covers only part of it (metres). */
static const noise_fbm drift = {.wavelength = 14.0, .octaves = 4, .gain = 0.5f, .seed = 0x5eu};
#define DRIFT_SAMPLES 4096         /* points of the drift noise its quantiles are read from */
#define DRIFT_SOFT 0.04            /* half-width of the edge of a snow patch, in noise units */

static double smooth_step(double e0, double e1, double x)
{
    double t = (x - e0) / (e1 - e0);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return t * t * (3.0 - 2.0 * t);
}

const char *ground_kind_name(ground_kind k)
{
    static const char *const names[GROUND_KINDS] = {"meadow", "forest floor", "soil", "rock",
                                                    "scree", "snow", "water"};
    return (unsigned)k < GROUND_KINDS ? names[k] : "?";
}

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The drift noise value below which a share `cover` of the ground lies: the quantile of the
 * noise over DRIFT_SAMPLES points of a 2 km square (a fixed, irregular pattern). */
static int snow_edge(ground_cover_map *m, err_buf *err)
{
    double *v = malloc(DRIFT_SAMPLES * sizeof *v); /* owned here */
    if (!v) return err_nomem(err, "out of memory for the snow cover");
    for (uint32_t k = 0; k < DRIFT_SAMPLES; k++) {
        uint64_t key = rng_combine(rng_hash_str("snow drift"), k);
        v[k] = noise_fbm2(&drift, 2000.0 * rng_u01f(key), 2000.0 * rng_u01f(rng_mix64(key)), 0.0, NULL);
    }
    qsort(v, DRIFT_SAMPLES, sizeof *v, compare_double);
    double at = m->snow.cover * (DRIFT_SAMPLES - 1);
    uint32_t k = (uint32_t)at;
    m->snow_edge = k + 1 < DRIFT_SAMPLES ? v[k] + (at - k) * (v[k + 1] - v[k]) : v[DRIFT_SAMPLES - 1];
    free(v);
    return 0;
}

/* Radius of a prototype's crown: half the mean of its footprint's width and depth. */
static double crown_radius(const mesh *m)
{
    float lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (uint32_t v = 0; v < m->nv; v++)
        for (int c = 0; c < 2; c++) lo[c] = fminf(lo[c], m->pos[3 * v + c]), hi[c] = fmaxf(hi[c], m->pos[3 * v + c]);
    return m->nv ? 0.25 * ((double)(hi[0] - lo[0]) + (hi[1] - lo[1])) : 0.0;
}

/* The crown cover of every plant instance, as a raster over their extent. */
static int build_canopy(ground_cover_map *m, const scene *s, err_buf *err)
{
    if (!s->n_instances) return 0;
    double *radius = malloc((s->n_prototypes ? s->n_prototypes : 1) * sizeof *radius); /* owned here */
    if (!radius) return err_nomem(err, "out of memory for the canopy of %u plants", s->n_instances);
    for (uint32_t p = 0; p < s->n_prototypes; p++) radius[p] = crown_radius(s->prototypes[p].mesh);
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (uint32_t i = 0; i < s->n_instances; i++) {
        if (scene_instance_is_ground_cover(s, i)) continue; /* tufts are no canopy */
        const xform3x4 *xf = &s->instances[i].xf;
        double sc = sqrt(xf->m[0][0] * xf->m[0][0] + xf->m[1][0] * xf->m[1][0] + xf->m[2][0] * xf->m[2][0]);
        double r = CROWN_REACH * radius[s->instances[i].prototype] * sc;
        for (int c = 0; c < 2; c++) lo[c] = fmin(lo[c], xf->m[c][3] - r), hi[c] = fmax(hi[c], xf->m[c][3] + r);
    }
    double span = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(span > 0) || !isfinite(span)) {
        free(radius);
        return 0;
    }
    m->cell = fmax(CANOPY_MIN_CELL, span / (CANOPY_MAX_CELLS - 1));
    m->cnx = (uint32_t)ceil((hi[0] - lo[0]) / m->cell) + 2, m->cny = (uint32_t)ceil((hi[1] - lo[1]) / m->cell) + 2;
    m->cx0 = lo[0] - 0.5 * m->cell, m->cy0 = lo[1] - 0.5 * m->cell;
    m->canopy = calloc((size_t)m->cnx * m->cny, sizeof *m->canopy);
    if (!m->canopy) {
        free(radius);
        return err_nomem(err, "out of memory for a %u x %u canopy raster", m->cnx, m->cny);
    }
    for (uint32_t i = 0; i < s->n_instances; i++) {
        if (scene_instance_is_ground_cover(s, i)) continue;
        const instance *in = &s->instances[i];
        const xform3x4 *xf = &in->xf;
        double sc = sqrt(xf->m[0][0] * xf->m[0][0] + xf->m[1][0] * xf->m[1][0] + xf->m[2][0] * xf->m[2][0]);
        double r = radius[in->prototype] * sc, reach = CROWN_REACH * r;
        double h = s->prototypes[in->prototype].height * sc;
        double opacity = 0.9 * smooth_step(CROWN_LOW_HEIGHT, CROWN_FULL_HEIGHT, h);
        if (!(r > 0)) continue;
        double px = xf->m[0][3], py = xf->m[1][3];
        int64_t i0 = (int64_t)floor((px - reach - m->cx0) / m->cell), i1 = (int64_t)ceil((px + reach - m->cx0) / m->cell);
        int64_t j0 = (int64_t)floor((py - reach - m->cy0) / m->cell), j1 = (int64_t)ceil((py + reach - m->cy0) / m->cell);
        for (int64_t j = j0 < 0 ? 0 : j0; j <= j1 && j < m->cny; j++)
            for (int64_t k = i0 < 0 ? 0 : i0; k <= i1 && k < m->cnx; k++) {
                double dx = m->cx0 + k * m->cell - px, dy = m->cy0 + j * m->cell - py;
                double cover = opacity * smooth_step(reach, CROWN_FULL * r, sqrt(dx * dx + dy * dy));
                float *c = &m->canopy[(size_t)j * m->cnx + k];
                *c = (float)(1.0 - (1.0 - *c) * (1.0 - cover));
            }
    }
    free(radius);
    return 0;
}

ground_cover_map *ground_cover_map_new(const scene *s, err_buf *err)
{
    const sylva_heightfield *hf = s->terrain;
    if (!hf || !SYLVA_HAS_FIELD(hf, sylva_heightfield, humidity) || !hf->has_ground_rules) return NULL;
    ground_cover_map *m = calloc(1, sizeof *m);
    if (!m) {
        err_nomem(err, "out of memory for the ground cover");
        return NULL;
    }
    m->hf = hf, m->rules = hf->ground, m->land = s->land_cover;
    float zlo = INFINITY, zhi = -INFINITY;
    for (size_t k = 0; k < (size_t)hf->nx * hf->ny; k++) zlo = fminf(zlo, hf->z[k]), zhi = fmaxf(zhi, hf->z[k]);
    m->band = fmax(1.0, 0.03 * ((double)zhi - zlo));
    m->slope_step = fmin(hf->dx, hf->dy);
    if (hf->n_levels) m->slope_step /= hf->levels[hf->n_levels - 1].refine; /* the finest level's */
    m->slope_step = fmax(0.5, m->slope_step);
    m->snow = s->snow;
    m->rest = (float)(GROUND_MEADOW_REST_SHARE * meadow_dormancy(s->season_day));
    if (build_canopy(m, s, err) || (m->snow.on && snow_edge(m, err))) {
        ground_cover_map_free(m);
        return NULL;
    }
    return m;
}

void ground_cover_map_free(ground_cover_map *m)
{
    if (!m) return;
    free(m->canopy);
    free(m);
}

/* Slope in degrees at (x, y): central differences of the drawn heights one step apart, which is
 * continuous wherever the heights are (across cells and levels alike). */
static double slope_at(const ground_cover_map *m, double x, double y)
{
    double h = m->slope_step;
    double zx = heightfield_height_clamped(m->hf, x + h, y) - heightfield_height_clamped(m->hf, x - h, y);
    double zy = heightfield_height_clamped(m->hf, x, y + h) - heightfield_height_clamped(m->hf, x, y - h);
    return atan(sqrt(zx * zx + zy * zy) / (2.0 * h)) * (180.0 / M_PI);
}

/* Bilinear lookup of a raster of nx x ny samples, sample (0, 0) at (x0, y0), spacing (dx, dy),
 * clamped at the edges. */
static double raster_at(const float *v, uint32_t nx, uint32_t ny, double x0, double y0, double dx, double dy,
                        double x, double y)
{
    double gx = (x - x0) / dx, gy = (y - y0) / dy;
    gx = gx < 0 ? 0 : gx > nx - 1 ? nx - 1 : gx;
    gy = gy < 0 ? 0 : gy > ny - 1 ? ny - 1 : gy;
    uint32_t i = gx >= nx - 1 ? nx - 2 : (uint32_t)gx, j = gy >= ny - 1 ? ny - 2 : (uint32_t)gy;
    double fx = gx - i, fy = gy - j;
    const float *r0 = v + (size_t)j * nx + i, *r1 = r0 + nx;
    return (1 - fy) * ((1 - fx) * r0[0] + fx * r0[1]) + fy * ((1 - fx) * r1[0] + fx * r1[1]);
}

float ground_cover_canopy(const ground_cover_map *m, double x, double y)
{
    if (!m->canopy || m->cnx < 2 || m->cny < 2) return 0.0f;
    return (float)raster_at(m->canopy, m->cnx, m->cny, m->cx0, m->cy0, m->cell, m->cell, x, y);
}

float ground_cover_dryness(const ground_cover_map *m, double x, double y)
{
    const sylva_heightfield *hf = m->hf;
    if (!hf->humidity) return m->rest;
    double hum = raster_at(hf->humidity, hf->nx, hf->ny, hf->x0, hf->y0, hf->dx, hf->dy, x, y);
    hum += 0.05 * noise_fbm2(&patch, x, y, 0.0, NULL);
    double d = m->rules.dry_humidity;
    float dry = (float)smooth_step(d + 0.08, d - 0.08, hum);
    return 1.0f - (1.0f - dry) * (1.0f - m->rest); /* the season's rest tints the lush meadow too */
}

/* The scene's lying snow at (x, y): above its height (z moved by the patch noise), where the
 * drift leaves it when it covers only part of the ground, and off steep ground as the snow line's
 * snow slides off. */
static double lying_snow(const ground_cover_map *m, double x, double y, double z, double slope)
{
    const snow_settings *s = &m->snow;
    double b = m->band;
    double above = s->min_height > -HUGE_VAL ? smooth_step(s->min_height - b, s->min_height + b, z) : 1.0;
    double lies = s->cover >= 1   ? 1.0
                  : s->cover <= 0 ? 0.0
                                  : smooth_step(m->snow_edge + DRIFT_SOFT, m->snow_edge - DRIFT_SOFT,
                                                noise_fbm2(&drift, x, y, 0.0, NULL));
    return above * lies * smooth_step(60.0, 40.0, slope);
}

void ground_cover_weights(const ground_cover_map *m, double x, double y, float w[GROUND_KINDS])
{
    const sylva_ground_rules *r = &m->rules;
    const sylva_heightfield *hf = m->hf;
    double z = heightfield_height_clamped(hf, x, y), slope = slope_at(m, x, y);
    double nw = noise_fbm2(&wander, x, y, 0.0, NULL), np = noise_fbm2(&patch, x, y, 0.0, NULL);
    double nb = noise_fbm2(&bare, x, y, 0.0, NULL);
    double b = m->band;
    /* each kind's share of what the kinds before it leave: water, rock, snow, scree, litter,
     * soil; the meadow takes the rest */
    double share[GROUND_KINDS] = {0};
    share[GROUND_WATER] = hf->has_water ? smooth_step(hf->water_level + 0.6, hf->water_level - 0.1, z + 0.3 * np) : 0.0;
    share[GROUND_ROCK] = smooth_step(r->rock_slope - 10.0, r->rock_slope + 2.0, slope + 8.0 * nw);
    share[GROUND_SNOW] = smooth_step(r->snow_z - b, r->snow_z + b, z + b * np) * smooth_step(60.0, 40.0, slope);
    if (m->snow.on) share[GROUND_SNOW] = fmax(share[GROUND_SNOW], lying_snow(m, x, y, z + b * np, slope));
    share[GROUND_SCREE] = fmax(smooth_step(r->scree_slope - 8.0, r->scree_slope + 4.0, slope + 8.0 * np),
                               smooth_step(r->scree_z - b, r->scree_z + b, z + b * nw));
    share[GROUND_FOREST_FLOOR] = smooth_step(0.25, 0.75, ground_cover_canopy(m, x, y) + 0.25 * np);
    share[GROUND_SOIL] = fmin(1.0, 0.6 * smooth_step(r->scree_slope - 8.0, r->scree_slope + 2.0, slope + 6.0 * nw) +
                                       0.5 * smooth_step(0.4, 0.65, nb));
    double land_rock = 0, land_soil = 0; /* the land cover's bare ground (docs/models/ground.md) */
    land_cover_bare_ground(m->land, x, y, &land_rock, &land_soil);
    share[GROUND_ROCK] = fmax(share[GROUND_ROCK], land_rock * smooth_step(-0.6, 0.2, nw));
    share[GROUND_SOIL] = fmax(share[GROUND_SOIL], land_soil * smooth_step(-0.4, 0.4, nb));
    static const ground_kind order[] = {GROUND_WATER, GROUND_ROCK, GROUND_SNOW, GROUND_SCREE,
                                        GROUND_FOREST_FLOOR, GROUND_SOIL};
    double left = 1.0;
    for (size_t k = 0; k < sizeof order / sizeof *order; k++) {
        w[order[k]] = (float)(left * share[order[k]]);
        left -= left * share[order[k]];
    }
    w[GROUND_MEADOW] = (float)left;
}
