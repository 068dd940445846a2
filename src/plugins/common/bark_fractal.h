/* bark_fractal.h — bark drawn from the escape-time pattern of the self-squaring map
 * z' = lambda z (1 - z) with |lambda| = 1 (lambda = e^{i theta}), Liu 003 §1, for every tree
 * plugin's bark texture.
 *
 * The texture's (u, v) is mapped onto an annulus of the complex plane round a centre: u is the
 * angle (one turn per texture width, so the pattern closes round the branch without a seam) and
 * v goes from the inner radius to the outer one and back ((1 - cos 2 pi v) / 2), so the texture
 * tiles along the branch too. Each point's escape time under the map becomes a height in
 * [0, 1]: low (a furrow) on the set's boundary, rising with the distance from the set (the
 * escape-time distance estimate) to 1 (a plate) at crack_width; points inside the set are
 * plates, so each furrow has one sloping and one steep flank. The albedo is the palette's furrow colour blended into its plate colour by height,
 * so its luminance rises with height: the renderer's bark bump (which reads the luminance
 * gradient of a bark texture as relief) sees furrows as grooves.
 *
 * Everything here is a pure function of its parameters: no random stream, no global state. */
#ifndef BARK_FRACTAL_H
#define BARK_FRACTAL_H

#include <stddef.h>
#include <stdint.h>

#define BARK_FRACTAL_ESCAPE_RADIUS 2.0 /* |z| > 2 never comes back: |z'| >= |z| (|z| - 1) > |z| */
#define BARK_FRACTAL_MAX_ITERATIONS 4096u

typedef struct bark_fractal_params {
    double theta;                      /* lambda = e^{i theta}, radians */
    double centre_re, centre_im;       /* centre of the annulus the texture covers */
    double radius_inner, radius_outer; /* its radii, 0 <= inner < outer */
    uint32_t iterations;               /* escape-time limit, 1 .. BARK_FRACTAL_MAX_ITERATIONS */
    double crack_width;                /* plane distance from the set at which a furrow's flank
                                        * reaches the plate, > 0 */
    double furrow[3], plate[3];        /* palette: linear RGB in [0, 1] at height 0 and 1 */
} bark_fractal_params;

/* The shipped barks, one per look the tree plugins name. */
typedef enum bark_fractal_preset {
    BARK_FRACTAL_SMOOTH,   /* beech-like: faint, wide-spaced lines */
    BARK_FRACTAL_SCALY,    /* spruce-like: small plates */
    BARK_FRACTAL_FURROWED, /* willow/oak-like: deep grooves running along the branch */
    BARK_FRACTAL_FISSURED, /* maple-like: long plates between fissures */
    BARK_FRACTAL_PRESETS
} bark_fractal_preset;

/* The parameters of a preset (grey palettes: a material's albedo multiplies them). */
bark_fractal_params bark_fractal_preset_params(bark_fractal_preset preset);

/* 0 when p is usable; otherwise -1 with a sentence naming the field, its value and the valid
 * range written into msg (msg_size bytes, NUL-terminated). */
int bark_fractal_check(const bark_fractal_params *p, char *msg, size_t msg_size);

/* The escape time of z0 under z' = e^{i theta} z (1 - z): the least n >= 0 with
 * |z_n| > BARK_FRACTAL_ESCAPE_RADIUS, or limit when no z_n with n < limit escapes. */
uint32_t bark_fractal_escape_count(double theta, double z0_re, double z0_im, uint32_t limit);

/* The escape time made continuous in z0 (the orbit is followed on to |z| > 256 and the count
 * is corrected by log2 of how far past that it went); limit for points that do not escape. */
double bark_fractal_escape_smooth(double theta, double z0_re, double z0_im, uint32_t limit);

/* The distance from z0 to the set of points that never escape, estimated from the escaping
 * orbit and its derivative (d = |z_n| ln|z_n| / (2 |dz_n/dz0|) once |z_n| > 256: within a small
 * factor of the true distance); 0 for a point that does not escape within limit steps. */
double bark_fractal_distance(double theta, double z0_re, double z0_im, uint32_t limit);

/* The point of the plane that texture coordinate (u, v) shows (periodic in u and v, period 1). */
void bark_fractal_point(const bark_fractal_params *p, double u, double v, double *re, double *im);

/* The height in [0, 1] at (u, v): 0 on the set's boundary, 1 from crack_width away and inside. */
double bark_fractal_height(const bark_fractal_params *p, double u, double v);

/* Fills height (width * height_px floats, row 0 at the top, v = 1) with the height at texel
 * centres. The caller owns the array. */
void bark_fractal_heights(const bark_fractal_params *p, uint32_t width, uint32_t height_px, float *height);

/* Fills rgba (width * height_px * 4 bytes, sRGB-encoded, row 0 at the top, alpha 255) with the
 * albedo from the heights (as bark_fractal_heights writes them). The caller owns both. */
void bark_fractal_albedo(const bark_fractal_params *p, uint32_t width, uint32_t height_px,
                         const float *height, uint8_t *rgba);

/* Fills rgba (width * height_px * 4 bytes, linear, alpha 255) with the tangent-space normal of
 * the height field scaled by relief (height units per texel width): x along +u, y along +v,
 * z out of the bark, each as 128 + 127 n. Differences wrap at every edge, as the texture does. */
void bark_fractal_normals(uint32_t width, uint32_t height_px, const float *height, double relief,
                          uint8_t *rgba);

#endif
