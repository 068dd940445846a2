/* gradient_noise.c — hashed gradient noise and its footprint-filtered octave sum (see
 * gradient_noise.h). */
#include "util/gradient_noise.h"

#include <math.h>
#include <stddef.h>

#define LACUNARITY 1.93
#define GOLDEN_COS (-0.7373688780783197) /* cos and sin of the golden angle, 2.39996 rad */
#define GOLDEN_SIN 0.6754902942615238
#define R2_A 0.7548776662466927 /* the R2 sequence's steps (Roberts 2018): 1/g and 1/g^2 for */
#define R2_B 0.5698402909980532 /* the plastic number g */
#define R2_SPAN 4096.0          /* lattice cells the octave origins spread over */

/* A 32-bit hash of a lattice node and a seed (Wellons' lowbias32 finaliser). */
static inline uint32_t node_hash(int64_t i, int64_t j, uint32_t seed)
{
    uint32_t h = seed ^ ((uint32_t)i * 0x8da6b343u) ^ ((uint32_t)j * 0xd8163841u) ^
                 ((uint32_t)(i >> 32) * 0x2c1b3c6du) ^ ((uint32_t)(j >> 32) * 0x297a2d39u);
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return h;
}

/* The node's gradient: one of eight unit directions, 45 degrees apart, by the hash. Eight are
 * enough: each octave is turned by its own angle, so no direction is shared across octaves. */
static const float gradients[8][2] = {{1, 0}, {0.70710678f, 0.70710678f}, {0, 1}, {-0.70710678f, 0.70710678f},
                                      {-1, 0}, {-0.70710678f, -0.70710678f}, {0, -1}, {0.70710678f, -0.70710678f}};

static inline void node_gradient(int64_t i, int64_t j, uint32_t seed, float *gx, float *gy)
{
    const float *g = gradients[node_hash(i, j, seed) >> 29];
    *gx = g[0], *gy = g[1];
}

float noise_gradient2(double x, double y, uint32_t seed, float grad[2])
{
    double fx0 = floor(x), fy0 = floor(y);
    int64_t i = (int64_t)fx0, j = (int64_t)fy0;
    float fx = (float)(x - fx0), fy = (float)(y - fy0);
    float ax, ay, bx, by, cx, cy, dx, dy;
    node_gradient(i, j, seed, &ax, &ay);
    node_gradient(i + 1, j, seed, &bx, &by);
    node_gradient(i, j + 1, seed, &cx, &cy);
    node_gradient(i + 1, j + 1, seed, &dx, &dy);
    float va = ax * fx + ay * fy, vb = bx * (fx - 1) + by * fy;
    float vc = cx * fx + cy * (fy - 1), vd = dx * (fx - 1) + dy * (fy - 1);
    float ux = fx * fx * fx * (fx * (fx * 6 - 15) + 10), uy = fy * fy * fy * (fy * (fy * 6 - 15) + 10);
    float k = va - vb - vc + vd;
    float v = va + ux * (vb - va) + uy * (vc - va) + ux * uy * k;
    if (grad) {
        float dux = 30 * fx * fx * (fx - 1) * (fx - 1), duy = 30 * fy * fy * (fy - 1) * (fy - 1);
        grad[0] = 1.41f * (ax + ux * (bx - ax) + uy * (cx - ax) + ux * uy * (ax - bx - cx + dx) +
                           dux * (uy * k + vb - va));
        grad[1] = 1.41f * (ay + ux * (by - ay) + uy * (cy - ay) + ux * uy * (ay - by - cy + dy) +
                           duy * (ux * k + vc - va));
    }
    return 1.41f * v;
}

float noise_fbm2(const noise_fbm *f, double x, double y, double footprint, float grad[2])
{
    double lambda = f->wavelength, amp = 1.0, total = 0.0, sum = 0.0, gx = 0.0, gy = 0.0;
    double c = 1.0, s = 0.0; /* octave k's rotation: k golden angles */
    uint32_t n = f->octaves > 32 ? 32 : f->octaves;
    for (uint32_t k = 0; k < n; k++) total += pow(f->gain, k);
    for (uint32_t k = 0; k < n; k++) {
        double r = footprint / lambda; /* 1 at a footprint a lattice cell wide */
        if (r >= 0.5) break;           /* this octave and every finer one average out */
        double w = r <= 0.25 ? 1.0 : 1.0 - (r - 0.25) / 0.25;
        w = w * w * (3.0 - 2.0 * w);
        double ox = R2_SPAN * fmod(0.5 + k * R2_A, 1.0), oy = R2_SPAN * fmod(0.5 + k * R2_B, 1.0);
        double u = (c * x + s * y) / lambda + ox, v = (-s * x + c * y) / lambda + oy;
        float g[2];
        float val = noise_gradient2(u, v, f->seed + 0x9e3779b9u * k, grad ? g : NULL);
        sum += amp * w * val;
        if (grad) { /* d(u, v)/d(x, y) is the rotation over lambda */
            gx += amp * w * (g[0] * c - g[1] * s) / lambda;
            gy += amp * w * (g[0] * s + g[1] * c) / lambda;
        }
        amp *= f->gain;
        lambda /= LACUNARITY;
        double c2 = c * GOLDEN_COS - s * GOLDEN_SIN;
        s = s * GOLDEN_COS + c * GOLDEN_SIN, c = c2;
    }
    if (grad) grad[0] = (float)(gx / total), grad[1] = (float)(gy / total);
    return (float)(sum / total);
}
