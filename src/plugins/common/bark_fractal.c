/* bark_fractal.c — the escape-time bark of z' = lambda z (1 - z), |lambda| = 1 (bark_fractal.h).
 * Owns the map's iteration, the uv-to-plane mapping, the height and the albedo and normal
 * textures drawn from it; it allocates nothing. */
#include "bark_fractal.h"

#include <math.h>
#include <stdio.h>

#define SMOOTH_RADIUS 256.0 /* the smooth count follows the orbit this far out */
#define SMOOTH_STEPS 64      /* past |z| > 2 it gets there within 9 steps; a bound all the same */

/* theta, centre, radii, iterations, crack width, furrow grey, plate grey */
static const struct {
    double theta, centre_re, centre_im, r0, r1;
    uint32_t iterations;
    double crack, furrow, plate;
} presets[BARK_FRACTAL_PRESETS] = {
    [BARK_FRACTAL_SMOOTH] = {3.0, 0.5, 0.0, 0.07, 0.9, 96, 0.02, 0.50, 0.86},
    [BARK_FRACTAL_SCALY] = {1.8, 0.5, 0.0, 0.1, 0.9, 160, 0.04, 0.30, 0.85},
    [BARK_FRACTAL_FURROWED] = {2.3999632297286531, 0.5, 0.0, 0.08, 0.9, 200, 0.06, 0.22, 0.90},
    [BARK_FRACTAL_FISSURED] = {0.9, 0.5, 0.0, 0.25, 1.1, 160, 0.04, 0.35, 0.85},
};

bark_fractal_params bark_fractal_preset_params(bark_fractal_preset preset)
{
    if ((unsigned)preset >= BARK_FRACTAL_PRESETS) preset = BARK_FRACTAL_SMOOTH;
    bark_fractal_params p = {.theta = presets[preset].theta,
                             .centre_re = presets[preset].centre_re,
                             .centre_im = presets[preset].centre_im,
                             .radius_inner = presets[preset].r0,
                             .radius_outer = presets[preset].r1,
                             .iterations = presets[preset].iterations,
                             .crack_width = presets[preset].crack};
    for (int k = 0; k < 3; k++) p.furrow[k] = presets[preset].furrow, p.plate[k] = presets[preset].plate;
    return p;
}

static int finite_in(double x, double lo, double hi) { return isfinite(x) && x >= lo && x <= hi; }

int bark_fractal_check(const bark_fractal_params *p, char *msg, size_t msg_size)
{
    if (!finite_in(p->theta, -1e6, 1e6))
        return snprintf(msg, msg_size, "bark theta %g: must be a finite angle in radians", p->theta), -1;
    if (!finite_in(p->centre_re, -1e6, 1e6) || !finite_in(p->centre_im, -1e6, 1e6))
        return snprintf(msg, msg_size, "bark centre (%g, %g): must be finite", p->centre_re, p->centre_im), -1;
    if (!finite_in(p->radius_inner, 0, 1e6) || !finite_in(p->radius_outer, 0, 1e6) ||
        !(p->radius_outer > p->radius_inner))
        return snprintf(msg, msg_size, "bark radii %g .. %g: need 0 <= inner < outer (finite)",
                        p->radius_inner, p->radius_outer), -1;
    if (p->iterations < 1 || p->iterations > BARK_FRACTAL_MAX_ITERATIONS)
        return snprintf(msg, msg_size, "bark iterations %u: must be 1 .. %u", p->iterations,
                        BARK_FRACTAL_MAX_ITERATIONS), -1;
    if (!finite_in(p->crack_width, 1e-9, 1e6))
        return snprintf(msg, msg_size, "bark crack_width %g: must be in [1e-9, 1e6]", p->crack_width), -1;
    for (int k = 0; k < 3; k++)
        if (!finite_in(p->furrow[k], 0, 1) || !finite_in(p->plate[k], 0, 1))
            return snprintf(msg, msg_size, "bark palette channel %d (%g, %g): must be in [0, 1]", k,
                            p->furrow[k], p->plate[k]), -1;
    return 0;
}

/* One step z' = lambda z (1 - z), lambda = (lr, li). */
static void step(double lr, double li, double *zr, double *zi)
{
    double wr = *zr - (*zr * *zr - *zi * *zi), wi = *zi - 2.0 * *zr * *zi; /* z - z^2 */
    *zr = lr * wr - li * wi;
    *zi = lr * wi + li * wr;
}

uint32_t bark_fractal_escape_count(double theta, double z0_re, double z0_im, uint32_t limit)
{
    double lr = cos(theta), li = sin(theta), zr = z0_re, zi = z0_im;
    const double r2 = BARK_FRACTAL_ESCAPE_RADIUS * BARK_FRACTAL_ESCAPE_RADIUS;
    for (uint32_t n = 0; n < limit; n++) {
        if (zr * zr + zi * zi > r2) return n;
        step(lr, li, &zr, &zi);
    }
    return limit;
}

double bark_fractal_escape_smooth(double theta, double z0_re, double z0_im, uint32_t limit)
{
    uint32_t n = bark_fractal_escape_count(theta, z0_re, z0_im, limit);
    if (n >= limit) return limit;
    /* Past the escape radius |z'| ~ |z|^2, so log|z| doubles per step: the count at which the
     * orbit passes SMOOTH_RADIUS, less log2 of how far past it went, varies continuously. */
    double lr = cos(theta), li = sin(theta), zr = z0_re, zi = z0_im;
    uint32_t m = 0;
    while (zr * zr + zi * zi <= SMOOTH_RADIUS * SMOOTH_RADIUS && m < n + SMOOTH_STEPS) step(lr, li, &zr, &zi), m++;
    double over = log(0.5 * log(zr * zr + zi * zi)) - log(log(SMOOTH_RADIUS));
    double nu = (double)m - over / log(2.0);
    return nu < 0 ? 0 : nu > limit ? limit : nu;
}

double bark_fractal_distance(double theta, double z0_re, double z0_im, uint32_t limit)
{
    if (bark_fractal_escape_count(theta, z0_re, z0_im, limit) >= limit) return 0.0;
    /* dz_{n+1}/dz0 = lambda (1 - 2 z_n) dz_n/dz0; |lambda| = 1 drops out of the modulus */
    double lr = cos(theta), li = sin(theta), zr = z0_re, zi = z0_im, dr = 1.0, di = 0.0;
    for (uint32_t m = 0; zr * zr + zi * zi <= SMOOTH_RADIUS * SMOOTH_RADIUS && m < limit + SMOOTH_STEPS; m++) {
        double ar = 1.0 - 2.0 * zr, ai = -2.0 * zi, t = dr * ar - di * ai;
        di = dr * ai + di * ar, dr = t;
        step(lr, li, &zr, &zi);
    }
    double mod_z = sqrt(zr * zr + zi * zi), mod_d = sqrt(dr * dr + di * di);
    return mod_d > 0 ? mod_z * log(mod_z) / (2.0 * mod_d) : 0.0;
}

void bark_fractal_point(const bark_fractal_params *p, double u, double v, double *re, double *im)
{
    const double two_pi = 6.283185307179586;
    double r = p->radius_inner + (p->radius_outer - p->radius_inner) * 0.5 * (1.0 - cos(two_pi * v));
    *re = p->centre_re + r * cos(two_pi * u);
    *im = p->centre_im + r * sin(two_pi * u);
}

double bark_fractal_height(const bark_fractal_params *p, double u, double v)
{
    double re, im;
    bark_fractal_point(p, u, v, &re, &im);
    if (bark_fractal_escape_count(p->theta, re, im, p->iterations) >= p->iterations)
        return 1.0; /* inside the set: a plate like the far field */
    double t = bark_fractal_distance(p->theta, re, im, p->iterations) / p->crack_width;
    if (t >= 1.0) return 1.0;
    return sqrt(t * (2.0 - t)); /* a rounded flank: steep at the furrow's floor, level at the plate */
}

void bark_fractal_heights(const bark_fractal_params *p, uint32_t width, uint32_t height_px, float *height)
{
    for (uint32_t row = 0; row < height_px; row++)
        for (uint32_t x = 0; x < width; x++) {
            double u = (x + 0.5) / width, v = 1.0 - (row + 0.5) / height_px;
            height[(size_t)row * width + x] = (float)bark_fractal_height(p, u, v);
        }
}

static uint8_t srgb_byte(double linear)
{
    linear = linear < 0 ? 0 : linear > 1 ? 1 : linear;
    double s = linear <= 0.0031308 ? 12.92 * linear : 1.055 * pow(linear, 1 / 2.4) - 0.055;
    return (uint8_t)(s * 255.0 + 0.5);
}

void bark_fractal_albedo(const bark_fractal_params *p, uint32_t width, uint32_t height_px,
                         const float *height, uint8_t *rgba)
{
    for (size_t i = 0; i < (size_t)width * height_px; i++) {
        double h = height[i];
        for (int k = 0; k < 3; k++) rgba[i * 4 + k] = srgb_byte(p->furrow[k] + (p->plate[k] - p->furrow[k]) * h);
        rgba[i * 4 + 3] = 255;
    }
}

static uint8_t signed_byte(double x) { return (uint8_t)lround(128.0 + 127.0 * (x < -1 ? -1 : x > 1 ? 1 : x)); }

void bark_fractal_normals(uint32_t width, uint32_t height_px, const float *height, double relief,
                          uint8_t *rgba)
{
    for (uint32_t row = 0; row < height_px; row++)
        for (uint32_t x = 0; x < width; x++) {
            uint32_t xl = (x + width - 1) % width, xr = (x + 1) % width;
            uint32_t up = (row + height_px - 1) % height_px, down = (row + 1) % height_px;
            /* row 0 is v = 1: +v is up the rows */
            double hu = 0.5 * relief * (height[(size_t)row * width + xr] - height[(size_t)row * width + xl]);
            double hv = 0.5 * relief * (height[(size_t)up * width + x] - height[(size_t)down * width + x]);
            double len = sqrt(hu * hu + hv * hv + 1.0);
            uint8_t *px = rgba + ((size_t)row * width + x) * 4;
            px[0] = signed_byte(-hu / len), px[1] = signed_byte(-hv / len), px[2] = signed_byte(1.0 / len);
            px[3] = 255;
        }
}
