/* aono_config.h — the Aono–Kunii tree's settings as the model reads them (seed 000 §3.1–3.3),
 * the parameter schema they come from, and the limits the plugin enforces.
 *
 * aono_config_read() turns the host-validated parameters into an aono_config and checks what
 * the schema cannot: relations between parameters, fitted angle laws (13)–(15), contraction
 * ratios from the tree's dimensions (23)–(24), the segment count a pattern and level count
 * give. Angles are stored in degrees as the scene gives them; lengths in metres.
 *
 * Ownership: an aono_config owns its controller array and its copy of the scene file's name;
 * aono_config_release() frees both (and accepts a zeroed or partly filled config).
 */
#ifndef AONO_CONFIG_H
#define AONO_CONFIG_H

#include <stdint.h>

#include "aono_angle_law.h"
#include "aono_pattern.h"
#include "bark_fractal.h"
#include "leaf_affine.h"
#include "plugin_err.h"
#include "plugin_params.h"
#include "sylva/plugin.h"

#define AONO_MAX_LEVELS 30          /* schema bound on `levels` */
#define AONO_MAX_SEGMENTS (1u << 20) /* trunk + every branch of the full-grown tree, worst case */
#define AONO_MAX_CONTROLLERS 1024
#define AONO_MAX_LEAVES (1u << 22)  /* leaves of one model */
#define AONO_LEAF_TEXTURE_SIZE 128u /* square, the leaf's unit square */
#define AONO_LEAF_TEXTURE_SEED 1u   /* the chaos game's seed: every scene, the same leaves */
#define AONO_BARK_TEXTURE_SIZE 128u /* square, one circumference wide and long */

typedef enum aono_ri_method {
    AONO_RI_CONSTANT = 0,   /* method (1): RI given */
    AONO_RI_DIMENSIONS = 1, /* method (2): from H, H0, L by (23)–(24) */
    AONO_RI_RANDOM = 2      /* method (3): uniform in an interval, per branching */
} aono_ri_method;

typedef enum aono_del_mode {
    AONO_DEL_FIXED = 0, /* δ = DEL at every branching, as printed in (16) */
    AONO_DEL_SPIRAL = 1 /* δ = n DEL at level n: successive branchings turn by DEL */
} aono_del_mode;

typedef enum aono_leaf_placement {
    AONO_LEAVES_TIP = 0,  /* clustered at the tips of the leaf-bearing branches */
    AONO_LEAVES_ALONG = 1 /* spread along them */
} aono_leaf_placement;

/* A point controller of (25): FAC > 0 attracts, FAC < 0 inhibits. */
typedef struct aono_controller {
    double q[3];            /* Q(i), metres, the scene's (right-handed) coordinates */
    double fac;             /* FAC(i), metres of deviation per child tip */
    uint32_t line, column;  /* where the controller's position stands in the scene file */
} aono_controller;

typedef struct aono_config {
    /* structure (§3.1) */
    uint32_t levels;           /* n: branching levels of the full-grown tree */
    aono_pattern pattern;
    uint32_t lvt;              /* monopodial: index (0 or 1) of the child that continues */
    double ternary_probability; /* stochastic: probability of three children */
    uint32_t n_children;       /* children of a branching: 2, or 3 (ternary, stochastic max) */
    /* dimensions */
    double height;             /* H, metres */
    double trunk_length;       /* H0, metres: the trunk P_a P_b */
    double crown_diameter;     /* L, metres */
    double rko;                /* dichotomous method (2): R2 = RKO R1 */
    /* angles (13)–(16), degrees */
    aono_angle_law fi[AONO_MAX_CHILDREN];
    double sf;                 /* standard deviation of the angle's normal deviation */
    double del, gamma;         /* δ (DEL) and γ */
    aono_del_mode del_mode;
    /* contraction ratios: ri[] is the constant or derived R_i; random draws in ri_range */
    aono_ri_method ri_method;
    double ri[AONO_MAX_CHILDREN];
    double ri_range[2];
    /* deviations (25) */
    double deviation[3];       /* (Dx, Dy, Dz), metres per child tip */
    aono_controller *controllers; /* owned; n_controllers entries */
    uint32_t n_controllers;
    int preserve_length;       /* 1: renormalise a deviated child to its length ρ_i */
    char *file;                /* owned copy of the scene file's name, for messages from generate() */
    /* thickness (stage two) */
    double trunk_radius;       /* metres at the base of the trunk */
    double radius_reduction;   /* radius factor per level */
    double lateral_radius_ratio; /* extra factor on a child that does not continue its mother */
    uint32_t sides, min_sides; /* polygon sides of the trunk; the fewest of any branch */
    /* leaves */
    uint32_t leaf_count;       /* leaves on an outermost branch of the full-grown tree; 0: none */
    double leaf_reference_length; /* metres: that branch's nominal length H0 R̄^levels; a branch
                                     bears leaf_count leaves per this length */
    leaf_affine_maps leaf;     /* the leaf's affine maps (`leaf:`), drawn into its texture */
    double leaf_length;        /* metres: the side of the square leaf quad */
    aono_leaf_placement leaf_placement;
    uint32_t leaf_levels;      /* the outermost levels that bear leaves */
    double leaf_angle;         /* degrees between a leaf and its branch */
    double leaf_jitter;        /* degrees of random turn of each leaf */
    double leaf_color[3], leaf_transmittance[3], bark_color[3]; /* linear RGB */
    bark_fractal_params bark;  /* the bark texture's fractal (`bark:`, `bark_angle:`) */
} aono_config;

/* The parameter schema (static const data) of AONO_N_PARAMS entries. */
#define AONO_N_PARAMS 37
extern const sylva_param_spec aono_params[];

/* Reads and checks the block of `params` (its reader; the block validated against aono_params)
 * into *cfg. Returns SYLVA_OK; params->status when the code read a name the schema lacks (the
 * host has the sentence); or a negative status with err saying what is wrong and what would be
 * valid (and at which key of which block). *cfg is released on failure. */
int aono_config_read(plugin_params *params, aono_config *cfg, plugin_err *err);
void aono_config_release(aono_config *cfg);

/* Segments (trunk included) of a tree of `levels` levels when every branching has `children`
 * children: 1 + c + c^2 + ... + c^levels, saturating at UINT64_MAX. */
uint64_t aono_segment_bound(uint32_t children, uint32_t levels);

#endif
