/* vessel_texture.c — procedural bark (tileable lattice noise and cell edges) and leaf outlines
 * (affine-map leaves from the shared presets), written as sRGB-encoded RGBA8. */
#include "vessel_texture.h"

#include "leaf_affine.h"

#include <math.h>
#include <stddef.h>

/* --- patterns ------------------------------------------------------------------------------ */

static double hash01(int32_t x, int32_t y, uint32_t salt)
{
    uint32_t h = (uint32_t)x * 0x8da6b343u ^ (uint32_t)y * 0xd8163841u ^ salt * 0xcb1ab31fu;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return h * (1.0 / 4294967296.0);
}

static int32_t wrap(int32_t i, int32_t period) { return ((i % period) + period) % period; }

/* Value noise over [0, 1)^2 with px x py lattice cells, periodic in both directions. */
static double value_noise(double u, double v, int32_t px, int32_t py, uint32_t salt)
{
    double x = u * px, y = v * py;
    int32_t ix = (int32_t)floor(x), iy = (int32_t)floor(y);
    double fx = x - ix, fy = y - iy;
    fx = fx * fx * (3 - 2 * fx), fy = fy * fy * (3 - 2 * fy);
    double a = hash01(wrap(ix, px), wrap(iy, py), salt);
    double b = hash01(wrap(ix + 1, px), wrap(iy, py), salt);
    double c = hash01(wrap(ix, px), wrap(iy + 1, py), salt);
    double d = hash01(wrap(ix + 1, px), wrap(iy + 1, py), salt);
    return (a + (b - a) * fx) + ((c + (d - c) * fx) - (a + (b - a) * fx)) * fy;
}

/* Sum of octaves, each twice the frequency and half the weight; in [0, 1]. */
static double fbm(double u, double v, int32_t px, int32_t py, int octaves, uint32_t salt)
{
    double sum = 0, weight = 0.5, total = 0;
    for (int o = 0; o < octaves; o++) {
        sum += weight * value_noise(u, v, px << o, py << o, salt + (uint32_t)o);
        total += weight;
        weight *= 0.5;
    }
    return sum / total;
}

/* Distance from the nearest cell edge of a periodic jittered grid of cx x cy cells (F2 - F1 of
 * the cell points, measured in cell units of the x axis). */
static double cell_edge(double u, double v, int32_t cx, int32_t cy, uint32_t salt)
{
    double x = u * cx, y = v * cy, f1 = 1e9, f2 = 1e9;
    int32_t ix = (int32_t)floor(x), iy = (int32_t)floor(y);
    double aspect = (double)cx / cy;
    for (int32_t j = -1; j <= 1; j++)
        for (int32_t i = -1; i <= 1; i++) {
            int32_t gx = ix + i, gy = iy + j;
            double px = gx + 0.15 + 0.7 * hash01(wrap(gx, cx), wrap(gy, cy), salt);
            double py = gy + 0.15 + 0.7 * hash01(wrap(gx, cx), wrap(gy, cy), salt + 7);
            double dx = x - px, dy = (y - py) / aspect;
            double d = sqrt(dx * dx + dy * dy);
            if (d < f1) f2 = f1, f1 = d;
            else if (d < f2) f2 = d;
        }
    return f2 - f1;
}

static double smooth(double e0, double e1, double x)
{
    double t = (x - e0) / (e1 - e0);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return t * t * (3 - 2 * t);
}

static uint8_t srgb_byte(double linear)
{
    linear = linear < 0 ? 0 : linear > 1 ? 1 : linear;
    double s = linear <= 0.0031308 ? 12.92 * linear : 1.055 * pow(linear, 1 / 2.4) - 0.055;
    return (uint8_t)(s * 255.0 + 0.5);
}

static void put(uint8_t *rgba, uint32_t size, uint32_t x, uint32_t row, double grey, int inside)
{
    uint8_t *p = rgba + ((size_t)row * size + x) * 4;
    p[0] = p[1] = p[2] = srgb_byte(grey);
    p[3] = inside ? 255 : 0;
}

/* --- bark ---------------------------------------------------------------------------------- */

static double bark_at(vessel_bark_kind kind, double u, double v)
{
    switch (kind) {
    case VESSEL_BARK_SMOOTH: { /* grey, softly mottled, with a few dark horizontal lenticels */
        double m = 0.78 + 0.22 * (fbm(u, v, 4, 4, 4, 11) - 0.5);
        if (value_noise(u, v, 12, 48, 12) > 0.8) m -= 0.18;
        return m;
    }
    case VESSEL_BARK_SCALY: { /* small rounded plates with dark gaps */
        double e = cell_edge(u, v, 7, 9, 21);
        return 0.42 + 0.46 * smooth(0.0, 0.16, e) + 0.14 * (fbm(u, v, 8, 8, 3, 22) - 0.5);
    }
    case VESSEL_BARK_FURROWED: { /* deep ridges running along the branch */
        double phase = u * 7 + 0.45 * fbm(u, v, 3, 2, 3, 31);
        double r = fabs(sin(M_PI * phase));
        return 0.30 + 0.62 * pow(r, 0.7) + 0.12 * (fbm(u, v, 6, 12, 3, 32) - 0.5);
    }
    case VESSEL_BARK_FISSURED:
    default: { /* long plates between shallow fissures */
        double e = cell_edge(u, v, 5, 3, 41);
        return 0.5 + 0.4 * smooth(0.0, 0.1, e) + 0.12 * (fbm(u, v, 6, 6, 3, 42) - 0.5);
    }
    }
}

void vessel_texture_bark(vessel_bark_kind kind, uint8_t *rgba)
{
    const uint32_t n = VESSEL_BARK_TEXTURE_SIZE;
    for (uint32_t row = 0; row < n; row++)
        for (uint32_t x = 0; x < n; x++) {
            double u = (x + 0.5) / n, v = 1.0 - (row + 0.5) / n;
            put(rgba, n, x, row, bark_at(kind, u, v), 1);
        }
}

/* --- leaves -------------------------------------------------------------------------------- */

/* Each outline is an affine-map leaf (003 §2, leaf_affine.h) from the shared presets. */
int vessel_texture_leaf(vessel_leaf_shape shape, uint8_t *rgba)
{
    static const leaf_affine_preset preset[VESSEL_LEAF_SHAPES] = {
        [VESSEL_LEAF_SHAPE_OVATE] = LEAF_AFFINE_BEECH,
        [VESSEL_LEAF_SHAPE_NEEDLES] = LEAF_AFFINE_SPRUCE,
        [VESSEL_LEAF_SHAPE_LANCEOLATE] = LEAF_AFFINE_WILLOW,
        [VESSEL_LEAF_SHAPE_PALMATE] = LEAF_AFFINE_MAPLE,
    };
    leaf_affine_maps maps;
    leaf_affine_preset_maps(preset[(unsigned)shape < VESSEL_LEAF_SHAPES ? shape : 0], &maps);
    return leaf_affine_render(&maps, VESSEL_LEAF_TEXTURE_SIZE, VESSEL_LEAF_TEXTURE_SEED, rgba,
                              NULL, 0);
}
