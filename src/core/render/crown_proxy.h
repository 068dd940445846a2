/* crown_proxy.h — the coarsest level of detail of a plant: when its projected height in the
 * camera being rendered falls below image.crown_proxy pixels, camera rays meet its crown's
 * envelope (geometry/crown_hull.h), an opaque Lambertian surface, instead of its leaves and
 * branches. Every other ray (shadows, bounces) still meets the full plant, so the light on the
 * surroundings and on the envelope itself is unchanged.
 *
 * A crown a few pixels across holds thousands of sub-pixel leaves, sunlit and shaded; each camera
 * sample lands on one of them, so at 16 samples a distant forest is noise. The envelope is
 * smooth, and its reflectance (one RGB per species, per render setup) is calibrated so that the
 * mean radiance of the pixels it covers equals what the full plants give there: before the
 * render, the pixels whose centre ray meets an envelope of species s are traced with the full
 * plants (D_s) and with the envelopes at reflectance 1, split into the part whose camera ray met
 * an envelope of species t first (A_st, linear in t's reflectance, as a Lambertian albedo scales
 * every path through the first vertex) and the rest (B_s); the reflectances solve
 * D_s = B_s + sum_t k_t A_st (Gauss-Seidel, each k in [0, 1]).
 *
 * Shadow rays (from any surface) meet the envelopes of the distant plants instead of the plants,
 * and pass through them: each crossing of an envelope multiplies the ray's transmittance by
 * tau, where tau^2 = 1 - (sun rays the plant blocks) / (sun rays crossing its envelope), measured
 * per prototype at the sun's elevation over all azimuths, so the light under and beside a
 * distant crown keeps its mean without the dappled pattern of its leaves.
 *
 * A sparse crown lets camera rays through: its opacity is the share of rays at the camera's
 * elevation over all azimuths crossing the envelope that meet the plant's leaves or branches;
 * below one half, a camera ray meets the envelope with that probability (decided once per ray
 * and plant), else passes through, so a sparse young tree on the horizon shows the sky between
 * its branches rather than a pale ball calibrated to the sky's light. A denser crown is opaque
 * and its gaps' light goes into the calibrated reflectance.
 *
 * Ids: the proxies are one user geometry of the top scene (mask ACCEL_MASK_PROXY), primitive j
 * proxy j, whose hits carry the ids an instance of the envelope would: instID[0]
 * accel.first_proxy + j, geomID the envelope's part (an Embree instance per proxy would cost some
 * 400 bytes, as much again as the plant's own: docs/scale.md). The plant it stands for keeps its id with mask ACCEL_MASK_FAR_PLANT. Camera rays carry neither
 * ACCEL_MASK_FAR_PLANT nor, in verification mode, ACCEL_MASK_PROXY; every other ray lacks
 * ACCEL_MASK_PROXY (render_ctx.camera_mask, ray_mask).
 *
 * crown_proxy.c chooses the plants and builds the envelopes and their shadows; crown_calibrate.c
 * calibrates the reflectances (crown_calibrate.h).
 *
 * Ownership: a crown_proxies is owned by its accel (accel_free frees it); it owns the envelopes'
 * meshes, their Embree scenes and their materials. */
#ifndef SYLVA_CROWN_PROXY_H
#define SYLVA_CROWN_PROXY_H

#include "render/accel_types.h"
#include "render/camera.h"
#include "util/err.h"
#include "util/vec3.h"

typedef struct crown_proxies {
    uint32_t n_prototypes;
    mesh **hull;            /* per prototype: its crown's envelope, or NULL; owned */
    RTCScene *hull_scene;   /* per prototype with an envelope; owned (released) */
    geom_info *hull_geom;   /* ACCEL_PARTS per prototype (opaque part only used); owned */
    material *materials;    /* per species: Lambertian, the calibrated reflectance; owned */
    uint32_t n_species;
    uint32_t *plant;        /* per proxy: the plant instance it stands for; owned */
    float *hull_box;        /* per prototype: its envelope's bounds, lo xyz then hi xyz; owned */
    uint32_t n;             /* proxies in the top scene */
    vec3 sun;               /* unit, toward the sun: the envelopes' transmittance is measured along it */
    vec3 view;              /* the camera's forward direction: their opacity is measured along it */
} crown_proxies;

/* Adds to a (built by accel_build_open, before accel_commit) a crown proxy for every plant outside the development whose
 * species has a crown and whose projected height through camera c is below max_pixels, with
 * reflectance 1 until calibrated; sun (unit, toward it) sets the envelopes' transmittance. The
 * envelopes are built on up to `threads` threads (0: one per processor), the same for any
 * count. Nothing when max_pixels is 0. Returns 0, or -1 with err set. */
int crown_proxies_attach(accel *a, const camera *c, vec3 sun, double max_pixels, unsigned threads, err_buf *err);
void crown_proxies_free(crown_proxies *p); /* accepts NULL */

/* The context of a shadow ray that may cross envelopes: Embree's, then the transmittance so far
 * (start at 1) and the envelope triangles already counted (a triangle may be reported twice). */
enum { SHADOW_SEEN = 16 };
typedef struct shadow_context {
    struct RTCIntersectContext ic;
    float transmittance;
    uint32_t n_seen;
    unsigned seen_inst[SHADOW_SEEN], seen_prim[SHADOW_SEEN];
} shadow_context;

/* The proxy (index + 1) a camera ray's hit rh lies on, or 0. */
uint32_t crown_proxy_of_hit(const accel *a, const struct RTCRayHit *rh);

/* Shading data at a hit on proxy j (crown_proxy_of_hit - 1), as accel_shade gives. */
void crown_proxy_shade(const accel *a, uint32_t j, const struct RTCRayHit *rh, hit_info *h);

#endif
