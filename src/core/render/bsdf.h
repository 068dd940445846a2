/* bsdf.h — the two surface models: Lambertian reflection, and the two-sided translucent leaf.
 * Directions are unit and point away from the surface; n is the shading normal turned toward
 * wo. bsdf_eval returns f alone (no cosine).
 *
 * The leaf is a rough dielectric coat, the cuticle (render/leaf_coat.h: GGX, index 1.45), over
 * diffuse reflection with the albedo on the side of wo and diffuse transmission with the
 * transmittance to the other side:
 *   f = f_coat(wo, wi) + c (1 - E(mu_o)) (1 - E(|mu_i|)) / (pi (1 - E_avg)),
 * c the albedo (mu_i > 0) or the transmittance (mu_i < 0), E the coat's directional albedo and
 * E_avg its cosine-weighted mean. The under layer gets exactly what the coat does not reflect on
 * the way in and on the way out (Kelemen and Szirmay-Kalos 2001's coupling), so a leaf
 * returns E(mu_o) + (1 - E(mu_o)) (r + t) of the light: at most 1 when r + t <= 1, and f stays
 * reciprocal. Both faces carry the coat.
 *
 * Sampling: the coat with probability E(mu_o) / (E(mu_o) + (1 - E(mu_o)) (r + t)) (luminance),
 * else the two diffuse sides in proportion to r and t; bsdf_eval's pdf is that mixture's, so
 * next-event estimation and BSDF sampling weigh each other correctly (MIS). */
#ifndef SYLVA_BSDF_H
#define SYLVA_BSDF_H

#include "scene/scene.h"
#include "util/vec3.h"

typedef struct bsdf_sample {
    vec3 wi;
    vec3 f;        /* BSDF value for wi */
    float pdf;     /* solid angle */
} bsdf_sample;

/* f(wo, wi) and its sampling pdf. */
vec3 bsdf_eval(const material *m, vec3 albedo, vec3 n, vec3 wo, vec3 wi, float *pdf);
/* Samples wi from (u0 lobe choice, u1, u2). Returns 0 when no direction was produced. */
int bsdf_sample_dir(const material *m, vec3 albedo, vec3 n, vec3 wo, float u0, float u1, float u2,
                    bsdf_sample *out);
/* Probability of choosing the transmission lobe of a leaf once the coat is not chosen (0 for
 * Lambertian). */
float bsdf_transmit_probability(const material *m, vec3 albedo);

#endif
