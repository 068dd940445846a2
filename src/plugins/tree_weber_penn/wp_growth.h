/* wp_growth.h — a Weber–Penn tree while it grows, as Arbaro 1.9's StemImpl, SegmentImpl,
 * SubsegmentImpl and LeafImpl hold it: records in pools (wp_pool.h) linked by index, each stem
 * with its segments, child stems, clones and leaves in the order Arbaro made them. The growing
 * functions (wp_stem.c and the files beside it) fill it; the mesh (wp_mesh.h) and the model
 * (wp_model.c) read it. A failure (memory, a limit) is sticky: it is recorded once and every
 * function returns quickly after it. */
#ifndef WP_GROWTH_H
#define WP_GROWTH_H

#include <stddef.h>

#include "plugin_err.h"
#include "wp_frame.h"
#include "wp_pool.h"
#include "wp_prepare.h"

#define WP_NONE (-1)

/* Clones of clones nest at most this deep (each nesting is a recursion of the growing code;
 * real species nest fewer levels than they have segments per stem, a handful). */
#define WP_MAX_SPLIT_DEPTH 200

/* Stems shorter than this (metres), or thinner than a tenth of it, are not made (Arbaro's
 * MIN_STEM_LEN and MIN_STEM_RADIUS). */
#define WP_MIN_STEM_LEN 0.00001
#define WP_MIN_STEM_RADIUS (WP_MIN_STEM_LEN / 10)

/* A point where a stem's radius is known: a segment's end or a place inside it. */
typedef struct wp_subsegment {
    wp_vec pos;
    double rad;
    double dist; /* from the segment's base, metres */
} wp_subsegment;

typedef struct wp_segment {
    int stem;
    int index;            /* the segment's number along its stem (a clone's start past 0) */
    wp_frame transf;      /* its base and direction */
    double rad1, rad2;    /* radius at its base and top */
    double length;
    int sub_first, sub_count; /* its subsegments, contiguous in the pool */
    int next;             /* the stem's next segment */
} wp_segment;

typedef struct wp_leaf_rec {
    wp_frame transf;
    int next;             /* the stem's next leaf */
} wp_leaf_rec;

typedef struct wp_stem {
    int level;            /* 0 the trunk; may pass 3 (level 3's parameters then) */
    int parent;           /* the stem it grows from, WP_NONE for a trunk */
    int cloned_from;      /* for a clone: the stem it split from, else WP_NONE */
    int is_clone;
    int split_depth;      /* clones between it and the stem that did not split off */
    int index;            /* its number among its parent's children */
    wp_frame transf;
    double offset;        /* from the parent's base, metres */
    double length, segment_length, base_radius;
    int segment_count;
    double length_child_max, substems_per_segment, substem_rotangle, leaves_per_segment;
    double split_correction;
    int prune_test;       /* growing as a trial for pruning: no children, no leaves */
    int seg_first, seg_last;
    int child_first, child_last, n_children;
    int clone_first, clone_last;
    int leaf_first, leaf_last;
    int next;             /* the next child of its parent, or the next clone of its original */
} wp_stem;

typedef struct wp_growth {
    wp_prepared *t;       /* borrowed */
    wp_pool stems, segments, subsegments, leaves; /* owned: wp_stem, wp_segment, ... */
    int trunk_first, trunk_last;
    double trunk_rotangle;
    size_t rings_made;    /* cross-sections with a radius made, outside pruning tests */
    size_t stems_tried;   /* stems begun, kept or not (too short, pruning trials) */
    size_t leaves_made;
    size_t max_triangles, max_leaves;
    int failed;           /* a negative sylva_status once a failure is recorded */
    plugin_err *err;      /* borrowed */
} wp_growth;

static inline wp_stem *wp_stem_at(const wp_growth *g, int i)
{
    return (wp_stem *)wp_pool_at(&g->stems, (size_t)i);
}

static inline wp_segment *wp_segment_at(const wp_growth *g, int i)
{
    return (wp_segment *)wp_pool_at(&g->segments, (size_t)i);
}

static inline wp_subsegment *wp_subsegment_at(const wp_growth *g, int i)
{
    return (wp_subsegment *)wp_pool_at(&g->subsegments, (size_t)i);
}

static inline wp_leaf_rec *wp_leaf_at(const wp_growth *g, int i)
{
    return (wp_leaf_rec *)wp_pool_at(&g->leaves, (size_t)i);
}

/* Appends record k to the list (first, last) whose last record's `next` is *last_next (NULL
 * when the list is empty). */
static inline void wp_list_append(int *first, int *last, int *last_next, int k)
{
    if (last_next)
        *last_next = k;
    else
        *first = k;
    *last = k;
}

/* An empty growth of the prepared species t, stopping past the limits. */
void wp_growth_init(wp_growth *g, wp_prepared *t, size_t max_triangles, size_t max_leaves, plugin_err *err);

/* Frees the pools. */
void wp_growth_free(wp_growth *g);

/* Records a failure (the first only) and returns it. */
int wp_growth_fail_nomem(wp_growth *g);

/* Records that the tree passes max_triangles (the first failure only) and returns it. */
int wp_growth_fail_triangles(wp_growth *g);

/* Grows every trunk and all they bear (Arbaro's TreeImpl.make). Returns 0 or g->failed. */
int wp_growth_grow(wp_growth *g);

/* --- used between the growing files --- */

/* A new stem of `level` growing from `grows_out_of` (WP_NONE for a trunk; a stem of the same
 * level makes it a clone) with frame trf at `offset`; its index, or WP_NONE on failure. */
int wp_stem_new(wp_growth *g, int grows_out_of, int level, wp_frame trf, double offset);

/* Makes stem s (StemImpl.make): its length, radius, pruning, segments and all it bears.
 * Returns 1 when the stem was made, 0 when it is too short or thin to be. */
int wp_stem_make(wp_growth *g, int s);

/* The stem's radius at h metres from its base (StemImpl.stemRadius). */
double wp_stem_radius(const wp_growth *g, const wp_stem *st, double h);

/* The leaves a stem of the last level bears (StemImpl.leavesPerBranch). */
double wp_stem_leaves_per_branch(const wp_growth *g, const wp_stem *st);

/* The stem's base radius (StemImpl.stemBaseRadius). */
double wp_stem_base_radius(const wp_growth *g, const wp_stem *st);

/* Makes segments start..end-1 of stem s with their children, leaves and clones (StemImpl
 * makeSegments). Returns, in a pruning test, the segment that left the envelope, else -1. */
int wp_stem_make_segments(wp_growth *g, int s, int start, int end);

/* Makes the segment's subsegments (SegmentImpl.make); 0, or -1 with g->failed set. */
int wp_segment_make(wp_growth *g, int seg);

/* The frame of a child stem or leaf at `where` (0..1) along segment seg (substemPosition). */
wp_frame wp_segment_child_position(const wp_growth *g, const wp_segment *seg, wp_frame trf, double where);

/* Splitting at segment nseg of stem s whose next frame is trf (makeClones). Returns, in a
 * pruning test, the segment of a clone that left the envelope, else -1. */
int wp_stem_make_clones(wp_growth *g, int s, wp_frame trf, int nseg);

/* Child stems and leaves of segment seg of stem s (makeSubstems, makeLeaves). */
void wp_stem_make_substems(wp_growth *g, int s, int seg);
void wp_stem_make_leaves(wp_growth *g, int s, int seg);

/* The next rotation angle of a stem's children (or the tree's trunks) about it, `*rotangle`
 * the last one: Rotate on from it (plus RotateV) when Rotate >= 0, else alternating sides at
 * 180 + Rotate (Arbaro's substemDirection and trunkDirection). */
double wp_next_rotation(double *rotangle, wp_level_state *lv);

/* The direction of a child stem or leaf at `offset` metres along stem s (substemDirection). */
wp_frame wp_stem_child_direction(wp_growth *g, wp_stem *st, wp_frame trf, double offset);

/* Pruning of stem s to the envelope (StemImpl.pruning). */
void wp_stem_prune(wp_growth *g, int s);

#endif
