/* bsdf.h — the two surface models: Lambertian reflection, and the two-sided translucent leaf
 * (diffuse reflection with albedo on the side the light comes from, diffuse transmission to the
 * other side). Directions are unit and point away from the surface; n is the shading normal
 * turned toward wo. Values are f * |cos| is NOT included: bsdf_eval returns f alone. */
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
/* Probability of choosing the transmission lobe of a leaf (0 for Lambertian). */
float bsdf_transmit_probability(const material *m, vec3 albedo);

#endif
