/* stock_mesh.h — the mesh of a young planted plant as nursery stock grows: a leader (the single
 * stem of a whip, a feathered tree or a standard), laterals along it (a feathered tree's side
 * shoots down most of its height, a standard's few crown branches over its clear stem), short
 * twigs on the longer laterals, the species' own leaf spread sparsely over the shoots, and the
 * spiral guard or stake it was planted with. What the shape holds (how tall, how wide, how many
 * laterals and leaves) is decided by planting_stock.h; this file only draws it, from a seed, so
 * the same shape and seed give the same mesh.
 *
 * The prototype frame is the plants': Z up, the stem's foot at the origin; the leader's tip is at
 * (about) (0, 0, height) and nothing of the plant stands higher than it.
 *
 * Ownership: stock_leaf_of fills a stock_leaf whose arrays the caller frees with
 * stock_leaf_release; stock_mesh_new returns a mesh the caller frees with mesh_free. */
#ifndef SYLVA_STOCK_MESH_H
#define SYLVA_STOCK_MESH_H

#include <stdint.h>

#include "scene/scene.h"

/* One leaf of a species' model, in its own frame: x along the leaf from one end (0 to length),
 * y across it, z along its normal. */
typedef struct stock_leaf {
    float *pos, *nrm, *uv;  /* 3, 3 and 2 floats per vertex; owned */
    uint32_t *tri;          /* 3 per triangle; owned */
    uint32_t nv, nt;
    int32_t material;       /* the leaf material of the species */
    double length, area;    /* metres, square metres (one side) */
} stock_leaf;

/* The first leaf of model m (leaf-material triangles joined by shared vertices, in the order the
 * plugin wrote them) when it is a leaf's size (at most 0.6 m long). Returns 1 found, 0 when the
 * model has no such leaf (*leaf left empty), -1 with err set (out of memory). */
int stock_leaf_of(const scene *s, const mesh *m, stock_leaf *leaf, err_buf *err);
void stock_leaf_release(stock_leaf *leaf); /* accepts an empty leaf */

/* What a young plant is drawn with. Lengths in metres. */
typedef struct stock_shape {
    double height;          /* the leader's tip above the foot */
    double stem_radius;     /* the leader at the ground */
    double crown_base;      /* the lowest lateral's height (a standard's clear stem) */
    double crown_radius;    /* the horizontal reach of the longest lateral */
    double lateral_spacing; /* along the leader, between laterals */
    double lateral_share;   /* 0 to 1: the share of the stations bearing a lateral (a whip's first shoots) */
    double lateral_angle;   /* from the vertical, degrees */
    int rounded;            /* 1: a standard's crown, widest in its middle; 0: conical, widest at its base */
    uint32_t leaves;        /* leaves on the whole plant */
    double guard_height;    /* a spiral guard round the stem's foot this tall; 0: none */
    double stake_height;    /* a stake beside the stem this tall; 0: none */
    int32_t bark, guard, stake; /* materials */
    const stock_leaf *leaf; /* the species' leaf, or NULL: no leaves */
} stock_shape;

/* The plant of shape sh drawn from seed (the same seed and shape, the same mesh). Returns the
 * mesh, or NULL with err set. */
mesh *stock_mesh_new(const stock_shape *sh, uint64_t seed, err_buf *err);

#endif
