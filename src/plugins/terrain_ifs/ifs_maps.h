/* ifs_maps.h — the maps w_{n,m} of the 3-D fractal interpolation IFS (Petric 1994, equations
 * (8)-(12); MODELS.md §1) for every DTM cell, and the probability field R that picks them.
 *
 * The maps are kept in unit coordinates of the DTM footprint, U = (x - x_1) / (x_N - x_1) and
 * V = (y - y_1) / (y_M - y_1), an affine change of variables that leaves (8)-(12) unchanged but
 * makes every DTM node an exactly representable point. For the cell whose south-west node is
 * (n, m) (0-based; the paper's map w_{n+2, m+2}):
 *
 *   L_n (8):      U' = u0 + U / (N - 1),             u0 = n / (N - 1)
 *   V_m (8):      V' = v0 + V / (M - 1),             v0 = m / (M - 1)
 *   F_{n,m} (9):  z' = c0 + cu U + cv V + cuv U V + alpha z
 *
 * with c0, cu, cv (and cuv) fixed by the corner conditions (10) with P, Q, S of (11):
 *   mode affine:   (0,0) -> z(n,m), (1,0) -> z(n+1,m), (1,1) -> z(n+1,m+1); cuv = 0. This is the
 *                  paper's three-condition map; its third condition uses z(x_n, y_m) as in (11),
 *                  not z(x_{n-1}, y_m) as printed in (10) (MODELS.md).
 *   mode bilinear: the fourth corner (0,1) -> z(n,m+1) as well, so every DTM node lies on the
 *                  attractor.
 * ifs_map_paper_coefficients gives the same map as the paper writes it, in metres.
 *
 * The maps are not stored: ifs_maps_cell computes a cell's map from its four DTM nodes when it
 * is needed (a few multiplications, against 64 bytes a cell read from memory), so the maps of a
 * 100-million-node DTM cost no memory beyond the DTM itself.
 *
 * Ownership: ifs_maps owns its probability and alias arrays; it borrows the DTM's heights and
 * the per-cell alpha field, which must outlive it. ifs_maps_free accepts NULL.
 */
#ifndef TERRAIN_IFS_MAPS_H
#define TERRAIN_IFS_MAPS_H

#include <stddef.h>
#include <stdint.h>

#include "dtm.h"
#include "plugin_err.h"

typedef enum ifs_mode {
    IFS_MODE_BILINEAR = 0, /* four corner conditions: the surface passes through every node */
    IFS_MODE_AFFINE = 1    /* the paper's three corner conditions (9)-(11) */
} ifs_mode;

/* One map w_{n,m}. */
typedef struct ifs_map {
    double c0, cu, cv, cuv; /* F_{n,m} without its alpha z term, in unit coordinates */
    double alpha;           /* alpha_{n,m}, in (-1, 1) */
    double u0, v0;          /* L_n(0) and V_m(0) in unit coordinates */
} ifs_map;

typedef struct ifs_maps {
    ifs_mode mode;
    uint32_t nx, ny;        /* DTM nodes N and M */
    uint32_t ncx, ncy;      /* cells N - 1 and M - 1 */
    uint32_t n_maps;        /* ncx * ncy */
    double su, sv;          /* 1 / ncx and 1 / ncy: the contraction of L_n and V_m */
    double width, depth;    /* x_N - x_1 and y_M - y_1, metres */
    const double *node_z;   /* the DTM heights, nx * ny, row 0 south; borrowed from the DTM */
    const double *alpha_field; /* alpha_{n,m} per cell (cell (n, m) at [m * ncx + n]), or NULL
                               for the global alpha; borrowed */
    double alpha;           /* the global alpha when alpha_field is NULL */
    double z11, zn1, znm, z1m; /* the heights of the four global corners (11) */
    double *probability;    /* R_{n,m} normalised to sum 1, per cell; NULL when uniform; owned */
    int uniform;            /* 1: every R_{n,m} is equal and picks skip the alias table */
    uint32_t *alias_cell;   /* Vose alias table of R (NULL when uniform); owned */
    uint32_t *alias_threshold; /* keep cell c when the low 32 bits are below this; owned */
    double alpha_max;       /* max |alpha_{n,m}| */
    double z_bound;         /* |z| <= z_bound for every point of the attractor and every point
                               the random iteration reaches from a start inside it */
    double corner_departure; /* largest |z - the bilinear surface of the four global corners|
                               over the DTM nodes: each cell holds a copy of this departure
                               scaled by its alpha, so alpha times it sizes the finest detail */
} ifs_maps;

typedef struct ifs_maps_params {
    ifs_mode mode;
    double alpha;               /* the global alpha, in (-1, 1); used when alpha_field is NULL */
    const double *alpha_field;  /* (N - 1) * (M - 1) per-cell alphas, row 0 the southern cells,
                                   or NULL */
    const double *probability;  /* (N - 1) * (M - 1) weights >= 0, not all 0, same order, or NULL
                                   for R proportional to the cell area */
} ifs_maps_params;

/* Builds the maps for a DTM, which must outlive them (so must p->alpha_field). Fails when an alpha lies outside (-1, 1), a weight is negative or
 * not finite, every weight is 0, or memory runs out. */
int ifs_maps_build(const ifs_dtm *dtm, const ifs_maps_params *p, ifs_maps **out, plugin_err *err);
void ifs_maps_free(ifs_maps *m);

/* The map of cell (n, m), 0-based, as (9)/(12) write it in metres with the footprint's first
 * node at (x1, y1): F(x, y, z) = a x + b y + e x y + alpha z + c (e = 0 in affine mode). */
void ifs_map_paper_coefficients(const ifs_maps *m, uint32_t n, uint32_t cell_m, double x1, double y1,
                                double *a, double *b, double *e, double *c);

/* The map of cell c = m * ncx + n, from the cell's four DTM nodes: (10) with P, Q, S (and T)
 * of (11). */
static inline ifs_map ifs_maps_cell(const ifs_maps *m, uint32_t c)
{
    uint32_t cn = c % m->ncx, cm = c / m->ncx;
    const double *z = m->node_z + (size_t)cm * m->nx + cn;
    double alpha = m->alpha_field ? m->alpha_field[c] : m->alpha;
    double P = z[0] - alpha * m->z11, Q = z[1] - alpha * m->zn1;
    double S = z[m->nx + 1] - alpha * m->znm, T = z[m->nx] - alpha * m->z1m;
    ifs_map w = {.c0 = P, .cu = Q - P, .alpha = alpha, .u0 = cn * m->su, .v0 = cm * m->sv};
    if (m->mode == IFS_MODE_AFFINE) w.cv = S - Q, w.cuv = 0.0;
    else w.cv = T - P, w.cuv = S - Q - T + P;
    return w;
}

/* The cell a 64-bit random number picks with probability R (high 32 bits choose a column of
 * the alias table, low 32 bits decide between it and its alias). */
static inline uint32_t ifs_maps_pick(const ifs_maps *m, uint64_t r)
{
    uint32_t c = (uint32_t)(((r >> 32) * (uint64_t)m->n_maps) >> 32);
    if (m->uniform) return c;
    return (uint32_t)r < m->alias_threshold[c] ? c : m->alias_cell[c];
}

#endif
