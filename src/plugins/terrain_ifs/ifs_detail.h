/* ifs_detail.h — how much relief the refinement adds, and the alpha that continues the DTM's own
 * roughness below what its nodes resolve (docs/models/terrain_ifs.md, "Detail from the DTM").
 *
 * The DTM's roughness is read at its two finest scales: the departure of its nodes from the
 * bilinear surface through every 2nd node, and through every 4th node, at the same relative
 * places (the middles of the coarse cells' sides and their centres). For a self-affine surface
 * the second is 2^H times the first (H the Hurst exponent). Nodes one cell apart resolve relief
 * of two cells' wavelength and longer, so the relief they leave out lies below half a cell: the
 * departure there, two octaves below the finest measured one, is the first over 4^H. That is the
 * texture the refinement adds; relief at the scales the DTM resolves is the DTM's own, and a
 * fractal copy laid over it at no particular place would only add to its error. The
 * refinement's detail is f_K - f_0 of ifs_eval.h sampled at points spread evenly over the
 * footprint; alpha is chosen so that its RMS equals that texture's. Nothing is allocated.
 */
#ifndef TERRAIN_IFS_DETAIL_H
#define TERRAIN_IFS_DETAIL_H

#include <stdint.h>

#include "dtm.h"
#include "ifs_maps.h"

#define IFS_DETAIL_SAMPLES 4096u /* points of the footprint the refinement's detail is measured at */
#define IFS_ALPHA_AUTO_MAX 0.5   /* the largest alpha the estimate gives */
#define IFS_DETAIL_REFINE 4u     /* depth 0: the auto depth of a grid this many times finer than the DTM */

typedef struct ifs_roughness {
    double half2;   /* RMS departure from the surface through every 2nd node, metres */
    double half4;   /* the same through every 4th node, at the same relative places */
    double all4;    /* through every 4th node, at all 15 of its places between them */
    double hurst;   /* log2(half4 / half2), as measured (not clamped) */
    double target;  /* RMS texture the measurement continues to, metres: half2 / 4^H with H
                       clamped to [0, 2], times all4 / half4 (the RMS over every place between
                       nodes against the middles' alone) */
} ifs_roughness;

/* Measures d. Returns 0, or -1 when d has fewer than 5 nodes along an axis (then the target is 0). */
int ifs_roughness_measure(const ifs_dtm *d, ifs_roughness *r);

/* The detail the maps add: f_depth - f_0 at IFS_DETAIL_SAMPLES points of a Halton sequence over
 * the footprint; its RMS and its largest magnitude, metres. depth 0: ifs_eval_auto_depth for a
 * grid IFS_DETAIL_REFINE times finer than the DTM. */
void ifs_detail_measure(const ifs_maps *m, uint32_t depth, double *rms, double *max);

/* The global alpha in [0, IFS_ALPHA_AUTO_MAX] whose detail (ifs_detail_measure, same mode and
 * depth) has RMS `target` metres on d: found by secant steps, as the detail grows with alpha
 * almost in proportion. 0 for a target of 0. Returns 0, or a negative sylva_status with err set
 * (out of memory). */
int ifs_alpha_for_detail(const ifs_dtm *d, ifs_mode mode, uint32_t depth, double target, double *alpha,
                         plugin_err *err);

#endif
