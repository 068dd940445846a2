/* gradient_noise.h — aperiodic 2-D gradient noise and its sum over octaves (fractal Brownian
 * motion), in world coordinates, with analytic gradients and filtering by a footprint.
 *
 * The lattice noise is Perlin's gradient noise with the quintic fade (Perlin 2002, "Improving
 * noise"): a gradient per lattice node from a hash of the node's integer coordinates and a
 * seed (no permutation table, so no period short of 2^32 cells). Octave k has wavelength
 * wavelength / 1.93^k (a lacunarity that is not a whole number, so octaves never line up) and
 * is turned by k golden angles and shifted by the k-th point of the R2 low-discrepancy sequence,
 * so no two octaves share a lattice axis or origin. An octave whose wavelength is under four
 * footprints fades out and is gone at two: its mean (zero) is what a pixel that wide sees, so
 * distant ground averages instead of aliasing. Deterministic: a pure function of its inputs.
 */
#ifndef SYLVA_GRADIENT_NOISE_H
#define SYLVA_GRADIENT_NOISE_H

#include <stdint.h>

typedef struct noise_fbm {
    double wavelength;   /* metres: the coarsest octave's lattice spacing */
    uint32_t octaves;    /* at most 32 */
    float gain;          /* amplitude of octave k + 1 over octave k, in (0, 1) */
    uint32_t seed;       /* which field: different seeds are independent */
} noise_fbm;

/* Gradient noise at lattice point (x, y), about [-1, 1], 0 at every lattice node; its gradient
 * (per lattice unit) into grad when grad is not NULL. */
float noise_gradient2(double x, double y, uint32_t seed, float grad[2]);

/* The octave sum at (x, y) metres, normalised by the sum of all octaves' amplitudes (so about
 * [-1, 1] unfiltered, mean 0), its octaves filtered by footprint (metres; 0: none). Its gradient
 * per metre into grad when not NULL. */
float noise_fbm2(const noise_fbm *f, double x, double y, double footprint, float grad[2]);

#endif
