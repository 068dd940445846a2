/* wp_prepare.h — a species made ready to grow as Arbaro 1.9's Params.prepare makes it: the
 * per-level parameters as Arbaro holds them (a level it reads only for leaves keeps zeros
 * elsewhere, a level past it all zeros), one random stream per level seeded in a chain from the
 * tree's seed, the stream the trunk's mesh draws from, the tree's drawn size, the mesh points
 * per cross-section, and the running error values that spread splits, child stems and leaves.
 * Also the shape ratios of the paper's Table 1 with Arbaro's pruning envelope. */
#ifndef WP_PREPARE_H
#define WP_PREPARE_H

#include <stdint.h>

#include "plugin_err.h"
#include "wp_params.h"
#include "wp_random.h"

/* One level as Arbaro's LevelParams holds it while a tree grows. */
typedef struct wp_level_state {
    int level;                 /* 0 to 3 */
    wp_level v;                /* the values Arbaro reads at this level, zeros elsewhere */
    int mesh_points;           /* points per cross-section of a stem of this level */
    wp_random random;          /* this level's stream */
    double split_error;        /* splitErrorValue: clones carried from segment to segment */
    double substem_error;      /* substemErrorValue: child stems carried likewise */
    int64_t saved_state;       /* the stream and split error saved around a pruning test */
    double saved_split_error;
} wp_level_state;

typedef struct wp_prepared {
    const wp_params *p;        /* borrowed */
    int levels;
    wp_level_state lv[WP_LEVELS];
    wp_random mesh_random;     /* Params.random: the trunk's lobes and 0ScaleV, drawn while meshing */
    double leaves_error;       /* leavesErrorValue, for the whole tree */
    double scale_tree;         /* Scale + a draw in [-ScaleV, ScaleV] */
    double mesh_quality;       /* Smooth */
} wp_prepared;

/* Prepares species p for Arbaro's seed into *out (which borrows p). Refuses, as Arbaro does, a
 * level that splits with a zero split angle, and a tree of more than 4 levels (Arbaro 1.9 stops
 * with an error there). Returns 0 or a negative sylva_status with err set. */
int wp_prepare(const wp_params *p, int64_t seed, wp_prepared *out, plugin_err *err);

/* The level state of a stem of level `stem_level` (levels past 3 use level 3's). */
static inline wp_level_state *wp_level_of(wp_prepared *t, int stem_level)
{
    return &t->lv[stem_level < WP_LEVELS - 1 ? stem_level : WP_LEVELS - 1];
}

/* A random value in (-variation, variation) from the level's stream (Arbaro's var()). */
double wp_level_var(wp_level_state *lv, double variation);

/* The shape ratio of `shape` (0 to 8; 8 the pruning envelope) at `ratio` in [0, 1]. */
double wp_shape_ratio(const wp_prepared *t, double ratio, int shape);

#endif
