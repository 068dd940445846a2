/* aono_grow.h — the tree's skeleton: the trunk P_a P_b and, level by level, every child branch
 * of every mother (seed 000 §3.2–3.3): angles from the laws (13)–(15) plus the deviation SF,
 * divergence δ and γ, lengths ρ_i = R_i ρ_op, tips placed in the mother's frame (16)–(19) and
 * deviated by (25).
 *
 * Segments are stored level by level (breadth first), so a mother always precedes its children
 * and the children of one mother are contiguous. Every random number comes from the stream
 * the caller's aono_env starts for the mother's node id (its path from the trunk; the plugin
 * file hands in the host's streams), so the tree does not depend on the order of work.
 *
 * Ownership: an aono_skeleton owns its segment array; aono_skeleton_release() frees it and
 * accepts a zeroed skeleton.
 */
#ifndef AONO_GROW_H
#define AONO_GROW_H

#include <stdint.h>

#include "aono_config.h"
#include "plugin_err.h"
#include "sylva/plugin.h"

#define AONO_NONE UINT32_MAX

/* What the model takes from outside: `stream` starts the random stream for (purpose, index),
 * `uniform` draws the next number in [0, 1) from one, `progress` (may be NULL) hears of each
 * level grown. Borrowed for the duration of a call. */
typedef struct aono_env {
    void (*stream)(void *ctx, sylva_rng *rng, const char *purpose, uint64_t index);
    double (*uniform)(sylva_rng *rng);
    void (*progress)(void *ctx, uint32_t levels_done, uint32_t levels);
    void *ctx;
} aono_env;

typedef struct aono_segment {
    double base[3], tip[3];  /* P_a and P_b of this branch, metres */
    double length;           /* ρ: the length its branching gave it (the next level's ρ_op) */
    double radius_base, radius_tip; /* metres */
    uint64_t node;           /* path id: trunk 1, child i of node m is 4 m + i + 1 */
    uint32_t parent;         /* mother's index, AONO_NONE for the trunk */
    uint32_t first_child;    /* index of the first child; children are contiguous */
    uint32_t continuation;   /* the child that continues this branch (shares its joint), or AONO_NONE */
    uint8_t level;           /* 0: trunk */
    uint8_t n_children;
    uint8_t child_index;     /* i of the branching that made it (0-based) */
    uint8_t continues;       /* 1 when it is its mother's continuation */
} aono_segment;

typedef struct aono_skeleton {
    aono_segment *seg;       /* owned: n segments, trunk first */
    uint32_t n, cap;
    uint32_t levels;         /* levels grown */
} aono_skeleton;

/* Grows a tree of `levels` levels (1 ... cfg->levels; fewer for a younger variant, whose trunk
 * radius is trunk_radius times radius_reduction^(cfg->levels − levels)) into *out
 * (which must be zeroed or released). Returns SYLVA_OK, or a negative status with err set (a
 * controller on a tip, SYLVA_ERR_PARAM; more than AONO_MAX_SEGMENTS, SYLVA_ERR_LIMIT; out of
 * memory, SYLVA_ERR_NOMEM); *out is then released. */
int aono_grow(const aono_config *cfg, uint32_t levels, const aono_env *env, aono_skeleton *out, plugin_err *err);
void aono_skeleton_release(aono_skeleton *s);

/* Deviation (25) of a child tip p (in place): p += (Dx, Dy, Dz) + Σ FAC(i) (Q(i) − p)/|Q(i) − p|,
 * the controllers seen from the undeviated tip; then, with preserve_length, p is put back at
 * distance rho from pb along the deviated direction. Returns 0, or -1 when p lies within
 * 1 µm of controller *which (its direction is undefined); p is then unchanged. */
int aono_deviate(const aono_config *cfg, const double pb[3], double rho, double p[3], uint32_t *which);

/* The branching angle φ_i of child i at level n (1 for the trunk's children) before the
 * stochastic deviation: the child's law, 0 for the continuing child of a monopodial branching. */
double aono_child_angle(const aono_config *cfg, uint32_t child, uint32_t level);

/* Azimuth of child i in its mother's frame at level n, degrees: δ for the first, δ + γ for the
 * second, δ + 180 + γ/2 (midway round the far side) for the third; δ = DEL, or n DEL in the
 * spiral mode. */
double aono_child_azimuth(const aono_config *cfg, uint32_t child, uint32_t level);

#endif
