/* ground_texture.c — the ground's albedo and micro-relief from the cover weights (see
 * ground_texture.h). */
#include "geometry/ground_texture.h"

#include <math.h>
#include <stdlib.h>

#include "geometry/texture_lookup.h"
#include "io/image_io.h"
#include "util/gradient_noise.h"
#include "util/srgb.h"

/* Measured mean albedos (linear RGB) of a temperate ground's kinds that no class stands for,
 * used when the terrain plugin gives no palette (ABI 1.6); the sources are in
 * docs/models/ground.md. */
static const vec3 litter_albedo = {0.11f, 0.075f, 0.045f};   /* beech and spruce leaf litter */
static const vec3 moss_albedo = {0.05f, 0.085f, 0.025f};     /* moss patches in the litter */
static const vec3 soil_albedo = {0.16f, 0.115f, 0.08f};      /* dry loam */
static const vec3 wet_soil_albedo = {0.075f, 0.055f, 0.04f}; /* the same, wet */
static const vec3 lichen_albedo = {0.26f, 0.25f, 0.18f};     /* crustose lichen on rock */

/* How one kind's colour and relief vary: its brightness by `tone` (a share of the mean), its
 * hue toward `tint` by `hue`, and its micro-relief (tilt per unit gradient of `relief`). */
typedef struct kind_texture {
    noise_fbm tone;
    float tone_amp;
    noise_fbm hue;
    float hue_amp;
    noise_fbm relief;
    float tilt;
} kind_texture;

static const kind_texture textures[GROUND_KINDS] = {
    [GROUND_MEADOW] = {{1.0, 9, 0.75f, 101}, 0.2f, {120.0, 10, 0.62f, 102}, 0.6f, {0.3, 6, 0.55f, 103}, 0.3f},
    [GROUND_FOREST_FLOOR] = {{2.0, 9, 0.6f, 201}, 0.4f, {6.0, 6, 0.5f, 202}, 0.6f, {0.4, 6, 0.55f, 203}, 0.4f},
    [GROUND_SOIL] = {{3.0, 9, 0.6f, 301}, 0.3f, {20.0, 6, 0.5f, 302}, 0.5f, {0.3, 6, 0.55f, 303}, 0.4f},
    [GROUND_ROCK] = {{6.0, 11, 0.62f, 401}, 0.35f, {1.5, 6, 0.5f, 402}, 0.4f, {2.0, 9, 0.6f, 403}, 0.6f},
    [GROUND_SCREE] = {{0.5, 7, 0.6f, 501}, 0.45f, {10.0, 5, 0.5f, 502}, 0.4f, {0.25, 5, 0.6f, 503}, 0.6f},
    [GROUND_SNOW] = {{5.0, 8, 0.5f, 601}, 0.06f, {50.0, 3, 0.5f, 602}, 0.0f, {2.0, 6, 0.5f, 603}, 0.15f},
    [GROUND_WATER] = {{1.0, 6, 0.5f, 701}, 0.2f, {10.0, 3, 0.5f, 702}, 0.0f, {1.0, 4, 0.5f, 703}, 0.05f},
};

/* Landscape-scale mottling shared by every kind: fields, drainage, exposure (kilometres to
 * tens of metres), as brightness. */
static const noise_fbm landscape = {.wavelength = 2000.0, .octaves = 8, .gain = 0.6f, .seed = 11};
#define LANDSCAPE_AMP 0.18f

#define BEYOND_SAMPLES 64u /* texels along each side averaged for the colour beyond the image */

static vec3 vec_of(const double v[3]) { return v3((float)v[0], (float)v[1], (float)v[2]); }

/* The colours of litter, soil and their tints: the terrain's palette (its biome's), else a
 * temperate ground's. */
static void set_palette(ground_texture *g, const sylva_heightfield *hf)
{
    const sylva_ground_palette *p =
        SYLVA_HAS_FIELD(hf, sylva_heightfield, palette) && hf->has_ground_palette ? &hf->palette : NULL;
    g->albedo[GROUND_FOREST_FLOOR] = p ? vec_of(p->litter_albedo) : litter_albedo;
    g->albedo[GROUND_SOIL] = p ? vec_of(p->soil_albedo) : soil_albedo;
    g->moss = p ? vec_of(p->moss_albedo) : moss_albedo;
    g->wet_soil = p ? vec_of(p->wet_soil_albedo) : wet_soil_albedo;
    g->lichen = p ? vec_of(p->lichen_albedo) : lichen_albedo;
}

int ground_texture_build(const scene *s, ground_texture **out, err_buf *err)
{
    *out = NULL;
    err_buf quiet = {0};
    ground_cover_map *m = ground_cover_map_new(s, &quiet);
    if (!m) return quiet.msg[0] ? err_nomem(err, "%s", quiet.msg) : 0;
    ground_texture *g = calloc(1, sizeof *g);
    if (!g) {
        ground_cover_map_free(m);
        return err_nomem(err, "out of memory for the ground's shading");
    }
    const sylva_ground_rules *r = &s->terrain->ground;
    g->map = m, g->hf = s->terrain;
    g->albedo[GROUND_MEADOW] = vec_of(r->grass_albedo);
    g->dry_grass = vec_of(r->dry_grass_albedo);
    set_palette(g, s->terrain);
    g->albedo[GROUND_ROCK] = vec_of(r->rock_albedo);
    g->albedo[GROUND_SCREE] = vec_of(r->scree_albedo);
    g->albedo[GROUND_SNOW] = vec_of(r->snow_albedo);
    g->albedo[GROUND_WATER] = g->wet_soil;
    /* the image's colour beyond the footprint: the mean of a regular sample of its texels */
    uint32_t iw, ih;
    double texel, sum[3] = {0, 0, 0};
    ground_texture_image_size(g->hf, &iw, &ih, &texel);
    for (uint32_t j = 0; j < BEYOND_SAMPLES; j++)
        for (uint32_t i = 0; i < BEYOND_SAMPLES; i++) {
            uint8_t rgb[3];
            ground_texture_image_texel(g, (uint32_t)((i + 0.5) * iw / BEYOND_SAMPLES),
                                       (uint32_t)((j + 0.5) * ih / BEYOND_SAMPLES), rgb);
            for (int k = 0; k < 3; k++) sum[k] += texture_srgb_to_linear(rgb[k]);
        }
    double n = (double)BEYOND_SAMPLES * BEYOND_SAMPLES;
    g->beyond = v3((float)(sum[0] / n), (float)(sum[1] / n), (float)(sum[2] / n));
    *out = g;
    return 0;
}

void ground_texture_free(ground_texture *g)
{
    if (!g) return;
    ground_cover_map_free(g->map);
    free(g);
}

/* The colour kind k's hue noise moves toward, given its mean. */
static vec3 hue_target(const ground_texture *g, ground_kind k)
{
    switch (k) {
    case GROUND_MEADOW: return g->dry_grass;
    case GROUND_FOREST_FLOOR: return g->moss;
    case GROUND_SOIL: return g->wet_soil;
    case GROUND_ROCK: return g->lichen;
    case GROUND_SCREE: return g->albedo[GROUND_ROCK];
    default: return g->albedo[k];
    }
}

static vec3 clamp_albedo(vec3 c)
{
    return v3(fminf(fmaxf(c.x, 0.0f), 0.98f), fminf(fmaxf(c.y, 0.0f), 0.98f), fminf(fmaxf(c.z, 0.0f), 0.98f));
}

/* Kind k's albedo at (x, y): its mean (the meadow's by its dryness), moved toward its tint and
 * scaled in brightness, both by noise whose mean is zero, so the filtered mean is the mean. */
static vec3 kind_albedo(const ground_texture *g, ground_kind k, double x, double y, double footprint)
{
    const kind_texture *t = &textures[k];
    vec3 mean = g->albedo[k];
    if (k == GROUND_MEADOW) {
        float dry = ground_cover_dryness(g->map, x, y);
        mean = v3_add(v3_scale(mean, 1.0f - dry), v3_scale(g->dry_grass, dry));
    }
    vec3 c = mean;
    if (t->hue_amp > 0.0f) {
        float h = t->hue_amp * noise_fbm2(&t->hue, x, y, footprint, NULL);
        c = v3_add(c, v3_scale(v3_sub(hue_target(g, k), mean), h));
    }
    float tone = 1.0f + t->tone_amp * noise_fbm2(&t->tone, x, y, footprint, NULL);
    return v3_scale(c, fmaxf(tone, 0.0f));
}

void ground_texture_image_size(const sylva_heightfield *hf, uint32_t *iw, uint32_t *ih, double *texel)
{
    double w = hf->dx * (hf->nx - 1), h = hf->dy * (hf->ny - 1);
    double t = fmax(fmax(w, h) / GROUND_TEXTURE_MAX_TEXELS, 0.5 * fmin(hf->dx, hf->dy));
    *iw = (uint32_t)ceil(w / t), *ih = (uint32_t)ceil(h / t);
    *texel = t;
}

void ground_texture_image_texel(const ground_texture *g, uint32_t c, uint32_t r, uint8_t rgb[3])
{
    const sylva_heightfield *hf = g->hf;
    uint32_t iw, ih;
    double t;
    ground_texture_image_size(hf, &iw, &ih, &t);
    double w = hf->dx * (hf->nx - 1), h = hf->dy * (hf->ny - 1);
    double x = hf->x0 + (c + 0.5) * w / iw, y = hf->y0 + h - (r + 0.5) * h / ih;
    float wt[GROUND_KINDS];
    ground_cover_weights(g->map, x, y, wt);
    vec3 a = ground_texture_albedo(g, x, y, t, wt);
    rgb[0] = srgb8_from_linear(a.x), rgb[1] = srgb8_from_linear(a.y), rgb[2] = srgb8_from_linear(a.z);
}

vec3 ground_texture_image_albedo(const ground_texture *g, double x, double y)
{
    const sylva_heightfield *hf = g->hf;
    uint32_t iw, ih;
    double t;
    ground_texture_image_size(hf, &iw, &ih, &t);
    double w = hf->dx * (hf->nx - 1), h = hf->dy * (hf->ny - 1);
    if (!(x >= hf->x0 && x <= hf->x0 + w && y >= hf->y0 && y <= hf->y0 + h)) return g->beyond;
    double gx = (x - hf->x0) / w * iw - 0.5, gy = (hf->y0 + h - y) / h * ih - 0.5; /* texel centres */
    gx = fmin(fmax(gx, 0.0), iw - 1.0), gy = fmin(fmax(gy, 0.0), ih - 1.0);
    uint32_t c0 = (uint32_t)gx, r0 = (uint32_t)gy;
    uint32_t c1 = c0 + 1 < iw ? c0 + 1 : c0, r1 = r0 + 1 < ih ? r0 + 1 : r0;
    double fx = gx - c0, fy = gy - r0;
    uint8_t q[4][3];
    ground_texture_image_texel(g, c0, r0, q[0]);
    ground_texture_image_texel(g, c1, r0, q[1]);
    ground_texture_image_texel(g, c0, r1, q[2]);
    ground_texture_image_texel(g, c1, r1, q[3]);
    float out[3];
    for (int k = 0; k < 3; k++)
        out[k] = (float)((1 - fy) * ((1 - fx) * texture_srgb_to_linear(q[0][k]) + fx * texture_srgb_to_linear(q[1][k])) +
                         fy * ((1 - fx) * texture_srgb_to_linear(q[2][k]) + fx * texture_srgb_to_linear(q[3][k])));
    return v3(out[0], out[1], out[2]);
}

vec3 ground_texture_albedo(const ground_texture *g, double x, double y, double footprint, const float w[GROUND_KINDS])
{
    vec3 c = v3(0, 0, 0);
    for (int k = 0; k < GROUND_KINDS; k++)
        if (w[k] > 1e-3f) c = v3_add(c, v3_scale(kind_albedo(g, (ground_kind)k, x, y, footprint), w[k]));
    float field = 1.0f + LANDSCAPE_AMP * noise_fbm2(&landscape, x, y, footprint, NULL);
    return clamp_albedo(v3_scale(c, field));
}

void ground_texture_relief(const ground_texture *g, double x, double y, double footprint, const float w[GROUND_KINDS],
                           float grad[2])
{
    double gx = 0.0, gy = 0.0;
    for (int k = 0; k < GROUND_KINDS; k++) {
        const kind_texture *t = &textures[k];
        if (w[k] <= 1e-3f || t->tilt <= 0.0f || footprint * 2.0 >= t->relief.wavelength) continue;
        float gr[2];
        noise_fbm2(&t->relief, x, y, footprint, gr);
        gx += w[k] * t->tilt * t->relief.wavelength * gr[0];
        gy += w[k] * t->tilt * t->relief.wavelength * gr[1];
    }
    grad[0] = (float)gx, grad[1] = (float)gy;
}

int ground_texture_write_image(const ground_texture *g, const char *path, err_buf *err)
{
    uint32_t iw, ih;
    double texel;
    ground_texture_image_size(g->hf, &iw, &ih, &texel);
    uint8_t *px = malloc((size_t)iw * ih * 3); /* owned here */
    if (!px) return err_nomem(err, "out of memory for the %ux%u image of the ground", iw, ih);
    for (uint32_t r = 0; r < ih; r++)
        for (uint32_t c = 0; c < iw; c++) ground_texture_image_texel(g, c, r, px + ((size_t)r * iw + c) * 3);
    int rc = image_write_u8(path, iw, ih, 3, px, err);
    free(px);
    return rc;
}
