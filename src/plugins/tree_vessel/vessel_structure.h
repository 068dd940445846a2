/* vessel_structure.h — Algorithm 2 of 004 (§3.4): the branch structure of one tree. The trunk's
 * S vessels split at every branching into a main child (S1) and a lateral child (S2); each call
 * of the algorithm is one segment (a vessel_branch) with its vessels, Gravelius and Weibull
 * orders, thickness, length and frame. Growth (3.33–3.34), level of detail (3.27–3.29) and the
 * still wind bend (3.35–3.38 at a frozen time) are applied while the structure is built.
 *
 * The structure is what the mesh is built from and what tests inspect: a flat list of segments
 * in the order Algorithm 2 visits them (a mother before her children, the lateral child's
 * subtree before the main child's), with the links between them.
 *
 * Frames: the tree frame is sylva's (Z up, metres, trunk base at the origin). Each segment's
 * local y axis is its axis (004 works with y up); the first segment's local x, y, z are the
 * tree's +X, +Z and -Y. */
#ifndef VESSEL_STRUCTURE_H
#define VESSEL_STRUCTURE_H

#include <stdint.h>

#include "plugin_err.h"
#include "vessel_params.h"
#include "vessel_tree.h"

/* What one build asks for beyond the species' parameters. */
typedef struct vessel_growth {
    double age;    /* normalised age t in (0, 1]: S' = t^2 S (3.33), l0' = t^2 l0 (3.34) */
    uint32_t lod;  /* l_LOD (3.27): 0 is full detail; 10 and above keep only the first segment */
    /* Numbers in [0, 1) for the per-branch wind phases R_x, R_z of 3.35, drawn two per
     * branching in the order of the list, only when wind_sway > 0. NULL: phases 0. */
    double (*uniform)(void *ctx);
    void *ctx;
} vessel_growth;

/* S' = t^2 S (3.33), rounded to the nearest whole vessel and at least 1. */
uint32_t vessel_grown_vessels(uint32_t vessels, double age);

/* Runs Algorithm 2 for p and the request g into *t (any previous content is released first).
 * Returns 0, or a sylva_status with err set: parameters that fail vessel_params_check, an age
 * outside (0, 1], or no memory. On failure *t is empty. */
int vessel_tree_grow(const vessel_params *p, const vessel_growth *g, vessel_tree *t,
                     plugin_err *err);

/* Frees the branch list and empties *t; accepts an empty tree. */
void vessel_tree_release(vessel_tree *t);

#endif
