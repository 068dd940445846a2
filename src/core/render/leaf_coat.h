/* leaf_coat.h — the leaf's cuticle as a rough dielectric layer: GGX microfacet reflection
 * (Walter et al. 2007, eq. 33 for D) with the exact unpolarised Fresnel reflectance of a
 * dielectric of index LEAF_CUTICLE_IOR and Smith's height-correlated masking-shadowing (Heitz
 * 2014, eq. 99), and its directional albedo E(mu) = integral of f_spec cos over the hemisphere,
 * tabulated once (deterministic quadrature) so the layer under it can take exactly what the coat
 * does not reflect (render/bsdf.h states the combination).
 *
 * Values: a cuticle index of 1.45 (cuticular wax and cutin; leaf optics models use 1.4 to 1.5,
 * PROSPECT's surface index is about 1.45 to 1.5 across the visible, Jacquemoud & Baret 1990)
 * and a GGX roughness alpha of 0.35 (Comar et al. 2014 fit Cook-Torrance roughness 0.18 to 0.56
 * to wheat and sorghum leaves; Bousquet et al. 2005 found the specular part of laurel, beech and
 * hazel leaves spectrally flat and shaped by surface roughness). At normal incidence the coat
 * reflects 3.4 %, under 10 % at most angles as McClendon (1984) measured for glabrous cuticles,
 * rising toward grazing: the sheen of leaves seen against the light. */
#ifndef SYLVA_LEAF_COAT_H
#define SYLVA_LEAF_COAT_H

#include "util/vec3.h"

#define LEAF_CUTICLE_IOR 1.45f
#define LEAF_CUTICLE_ALPHA 0.35f

/* Fresnel reflectance of unpolarised light arriving from air at cosine c on a dielectric of
 * relative index eta. */
float leaf_coat_fresnel(float c, float eta);
/* The coat's BRDF for unit wo, wi on the side of unit n (0 when either is below it) and its
 * sampling pdf over solid angle (the visible-normal-free D(h) cos(h) strategy). */
float leaf_coat_eval(vec3 n, vec3 wo, vec3 wi, float *pdf);
/* Samples wi by reflecting wo about a microfacet normal drawn from D(h) cos(h); 0 when the
 * reflected direction falls below the surface (no sample). */
int leaf_coat_sample(vec3 n, vec3 wo, float u1, float u2, vec3 *wi);
/* E(mu): the share of light arriving at cosine mu that the coat reflects, and its cosine-weighted
 * hemispherical mean E_avg = 2 integral E(mu) mu dmu. */
float leaf_coat_albedo(float mu);
float leaf_coat_albedo_mean(void);

#endif
