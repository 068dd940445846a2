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
#include "vessel_math.h"
#include "vessel_params.h"

typedef struct vessel_branch {
    vessel_vec base;       /* where the segment's axis starts, tree frame, metres */
    vessel_frame frame;    /* local axes in the tree frame; frame.c[1] is the axis */
    double length;         /* actual length l0 of this segment, metres */
    double rel_length;     /* relative length L0 */
    double diameter;       /* d = k_d sqrt(S0) at the base (3.4), metres */
    double tip_diameter;   /* the main child's d where the segment ends; 0: a cone to a point */
    double bark_v;         /* bark texture coordinate v at the base */
    uint32_t vessels;      /* S0 */
    uint32_t g, w;         /* Gravelius and Weibull orders */
    int32_t mother;        /* index of the mother segment; -1 for the first trunk segment */
    int32_t main_child;    /* index of the main child (S1 vessels); -1 when terminal */
    int32_t lateral_child; /* index of the lateral child (S2 vessels); -1 when terminal */
    uint8_t is_main;       /* 1: the main child of its mother, or the first trunk segment */
    uint8_t terminal;      /* 1: bears leaves (S0 = 1, or cut at w_geom by the level of detail) */
    uint8_t drawn;         /* 1: its cone is part of the mesh (w <= w_branch) */
} vessel_branch;

/* What one build asks for beyond the species' parameters. */
typedef struct vessel_growth {
    double age;    /* normalised age t in (0, 1]: S' = t^2 S (3.33), l0' = t^2 l0 (3.34) */
    uint32_t lod;  /* l_LOD (3.27): 0 is full detail; 10 and above keep only the first segment */
    /* Numbers in [0, 1) for the per-branch wind phases R_x, R_z of 3.35, drawn two per
     * branching in the order of the list, only when wind_sway > 0. NULL: phases 0. */
    double (*uniform)(void *ctx);
    void *ctx;
} vessel_growth;

typedef struct vessel_tree {
    vessel_branch *branches; /* n segments; owned, released by vessel_tree_release */
    uint32_t n;
    uint32_t vessels;        /* S' of this build */
    double trunk_length;     /* l0' of this build, metres */
    uint32_t n_terminal;     /* leaf-bearing segments */
    uint32_t w_geom, w_branch; /* the level of detail's limits (3.28, 3.29); UINT32_MAX: none */
    double height;           /* highest point of any segment's axis, metres */
} vessel_tree;

/* The bark texture's v where a segment ends: v grows by one per circumference of length, so
 * bark texels stay about square on thick and thin branches alike. */
static inline double vessel_bark_v_tip(const vessel_branch *b)
{
    double girth = M_PI * 0.5 * (b->diameter + b->tip_diameter);
    return b->bark_v + b->length / (girth > 1e-3 ? girth : 1e-3);
}

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
