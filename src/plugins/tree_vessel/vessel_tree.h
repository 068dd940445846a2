/* vessel_tree.h — the tree the vessel model grows: its segments (axis, frame, length, diameter,
 * vessels, orders, family) and the tree's figures of one build, with the bark texture's v at a
 * segment's tip. Built by vessel_structure.h, read by the ground, leaf and mesh stages.
 * Header-only. */
#ifndef VESSEL_TREE_H
#define VESSEL_TREE_H

#include <stdint.h>

#include "vessel_math.h"

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

#endif
