/* vessel_texture.c — the bark (the shared fractal bark, one preset per kind) and leaf outlines
 * (analytic shapes), written as sRGB-encoded RGBA8. */
#include "vessel_texture.h"

#include "bark_fractal.h"

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

/* The fractal bark (003 §1, bark_fractal.h) whose preset names the same look as the kind. */
static const bark_fractal_preset bark_presets[VESSEL_BARK_KINDS] = {
    [VESSEL_BARK_SMOOTH] = BARK_FRACTAL_SMOOTH,
    [VESSEL_BARK_SCALY] = BARK_FRACTAL_SCALY,
    [VESSEL_BARK_FURROWED] = BARK_FRACTAL_FURROWED,
    [VESSEL_BARK_FISSURED] = BARK_FRACTAL_FISSURED,
};

void vessel_texture_bark(vessel_bark_kind kind, uint8_t *rgba)
{
    const uint32_t n = VESSEL_BARK_TEXTURE_SIZE;
    bark_fractal_params p = bark_fractal_preset_params(bark_presets[(unsigned)kind < VESSEL_BARK_KINDS ? kind : 0]);
    float height[VESSEL_BARK_TEXTURE_SIZE]; /* one row at a time, at texel centres */
    for (uint32_t row = 0; row < n; row++) {
        double v = 1.0 - (row + 0.5) / n;
        for (uint32_t x = 0; x < n; x++) height[x] = (float)bark_fractal_height(&p, (x + 0.5) / n, v);
        bark_fractal_albedo(&p, n, 1, height, rgba + (size_t)row * n * 4);
    }
}

/* --- leaves -------------------------------------------------------------------------------- */

/* Distance from p to the segment a-b. */
static double segment_distance(double px, double py, double ax, double ay, double bx, double by)
{
    double dx = bx - ax, dy = by - ay, t = ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    double ex = px - (ax + t * dx), ey = py - (ay + t * dy);
    return sqrt(ex * ex + ey * ey);
}

/* A stalk up the middle from v = 0 to v = top. */
static int stalk(double x, double y, double top, double half_width)
{
    return y >= 0 && y <= top && fabs(x - 0.5) < half_width;
}

/* One ovate blade from (bx, by) along the unit direction (dx, dy): length len, widest
 * half-width half, pointed tip, wavy margin, a midrib and straight side veins. */
static int ovate_blade(double x, double y, double bx, double by, double dx, double dy, double len,
                       double half, double *grey)
{
    double a = (x - bx) * dx + (y - by) * dy, q = (x - bx) * dy - (y - by) * dx;
    double t = a / len;
    if (t < 0 || t > 1) return 0;
    double w = half * pow(sin(M_PI * pow(t, 0.75)), 0.9) * (1 + 0.05 * sin(t * 40));
    double aq = fabs(q);
    if (aq >= w) return 0;
    *grey = 0.8 + 0.12 * t;
    if (aq < 0.008 || fmod((a - 0.9 * aq) / len * 8 + 8, 1.0) < 0.08) *grey = 0.97;
    return 1;
}

/* Beech: a twig up the middle with ovate leaves on alternate sides and one at its end. */
static int leaf_ovate(double x, double y, double *grey)
{
    static const double at[4] = {0.1, 0.28, 0.46, 0.62};
    if (stalk(x, y, 0.7, 0.011)) {
        *grey = 0.6;
        return 1;
    }
    if (ovate_blade(x, y, 0.5, 0.64, 0, 1, 0.35, 0.15, grey)) return 1;
    for (int i = 0; i < 4; i++) {
        double side = (i & 1) ? -1 : 1, c = cos(0.95), s = sin(0.95);
        if (ovate_blade(x, y, 0.5, at[i], side * s, c, 0.45 - 0.03 * i, 0.16, grey)) return 1;
    }
    return 0;
}

/* Spruce: a twig up the middle with needles on both sides and along the top. */
static int leaf_needles(double x, double y, double *grey)
{
    *grey = 0.85;
    if (stalk(x, y, 0.98, 0.013)) {
        *grey = 0.55;
        return 1;
    }
    for (int i = 0; i < 24; i++) {
        double y0 = 0.03 + i * 0.04;
        double len = 0.4 * (1 - 0.55 * y0 * y0);
        for (int s = -1; s <= 1; s++) {
            double lean = s == 0 ? 0.35 * ((i & 1) ? 1 : -1) : s * 0.95; /* radians from the twig */
            double l = s == 0 ? 0.55 * len : len;
            double bx = 0.5 + l * sin(lean), by = y0 + l * cos(lean);
            double d = segment_distance(x, y, 0.5, y0, bx, by);
            double along = ((x - 0.5) * sin(lean) + (y - y0) * cos(lean)) / l;
            double width = 0.012 * (1 - 0.6 * (along < 0 ? 0 : along > 1 ? 1 : along));
            if (d < width) {
                *grey = 0.75 + 0.25 * along;
                return 1;
            }
        }
    }
    return 0;
}

/* Willow: a thin hanging shoot with long, narrow leaves on alternate sides, lying close to it. */
static int leaf_lanceolate(double x, double y, double *grey)
{
    if (stalk(x, y, 0.9, 0.008)) {
        *grey = 0.6;
        return 1;
    }
    for (int i = 0; i < 9; i++) {
        double y0 = 0.06 + i * 0.1, side = (i & 1) ? -1 : 1, lean = 0.32;
        double dx = side * sin(lean), dy = cos(lean), len = 0.3 - 0.012 * i;
        double a = (x - 0.5) * dx + (y - y0) * dy, q = (x - 0.5) * dy - (y - y0) * dx;
        double t = a / len;
        if (t < 0 || t > 1) continue;
        double half = 0.03 * pow(sin(M_PI * pow(t, 0.7)), 0.8);
        if (fabs(q) < half) {
            *grey = fabs(q) < 0.005 ? 0.97 : 0.8 + 0.12 * t;
            return 1;
        }
    }
    return 0;
}

/* Maple: five pointed lobes round a centre, toothed, with a vein to each lobe. */
static int leaf_palmate(double x, double y, double *grey)
{
    static const double lobe_angle[5] = {0.0, 0.84, -0.84, 1.75, -1.75};
    static const double lobe_length[5] = {0.5, 0.44, 0.44, 0.3, 0.3};
    const double cx = 0.5, cy = 0.42;
    *grey = 0.85;
    if (stalk(x, y, cy, 0.012)) return 1;
    double dx = x - cx, dy = y - cy, r = sqrt(dx * dx + dy * dy);
    double theta = atan2(dx, dy); /* from +v, clockwise toward +u */
    double reach = 0.16;
    for (int i = 0; i < 5; i++) {
        double d = theta - lobe_angle[i];
        double c = cos(1.7 * d);
        if (fabs(1.7 * d) < M_PI / 2 && c > 0) {
            double l = lobe_length[i] * pow(c, 1.6);
            if (l > reach) reach = l;
        }
        if (r * fabs(sin(d)) < 0.01 && cos(d) > 0 && r < lobe_length[i]) *grey = 0.98;
    }
    reach *= 1 + 0.06 * sin(theta * 36);
    return r < reach;
}

void vessel_texture_leaf(vessel_leaf_shape shape, uint8_t *rgba)
{
    const uint32_t n = VESSEL_LEAF_TEXTURE_SIZE;
    for (uint32_t row = 0; row < n; row++)
        for (uint32_t x = 0; x < n; x++) {
            double u = (x + 0.5) / n, v = 1.0 - (row + 0.5) / n, grey = 0;
            int inside;
            switch (shape) {
            case VESSEL_LEAF_SHAPE_OVATE: inside = leaf_ovate(u, v, &grey); break;
            case VESSEL_LEAF_SHAPE_NEEDLES: inside = leaf_needles(u, v, &grey); break;
            case VESSEL_LEAF_SHAPE_LANCEOLATE: inside = leaf_lanceolate(u, v, &grey); break;
            case VESSEL_LEAF_SHAPE_PALMATE:
            default: inside = leaf_palmate(u, v, &grey); break;
            }
            grey *= 0.92 + 0.16 * (value_noise(u, v, 16, 16, 51) - 0.5);
            put(rgba, n, x, row, grey, inside);
        }
}
