/* sylva/tree_stats.h — the optional interface "sylva.tree_stats.v1" of a tree plugin: the
 * figures of the model it built.
 * Part of the plugin ABI (sylva/plugin.h, whose version and rules it follows); plugin.h includes
 * it, so a plugin written against an older header compiles unchanged. */
#ifndef SYLVA_TREE_STATS_H
#define SYLVA_TREE_STATS_H

#include "sylva/plugin.h"

#ifdef __cplusplus
extern "C" {
#endif

/* =============================================================================================
 * Optional interface "sylva.tree_stats.v1": the figures of the model a tree plugin built.
 *
 * A tree plugin whose descriptor's extension(SYLVA_TREE_STATS_V1) returns a sylva_tree_stats_v1
 * table tells the host (`sylva tree-stats`) what its last successful generate() on a state
 * built: counts, bounds, the box-counting dimension of the side silhouette (002 eq. 3) and the
 * branch-number law's figures (002 eq. 6). A figure the plugin does not have is 0. The layouts
 * below are fixed under this id: a change is a new id.
 *
 * Ownership: the caller owns *out; the plugin writes no field at or past out->size bytes.
 */
#define SYLVA_TREE_STATS_V1 "sylva.tree_stats.v1"

typedef struct sylva_tree_stats {
    uint32_t size;            /* sizeof(sylva_tree_stats) as the caller compiled it */
    double age;               /* the request's normalised age */
    uint32_t recursion;       /* derivation (growth) steps the model used */
    uint64_t symbols;         /* symbols interpreted */
    uint64_t segments;        /* wood segments drawn */
    uint64_t leaves;          /* leaves (polygons) drawn */
    uint64_t branches;        /* branch count N of the branch-number law */
    uint64_t triangles;       /* triangles appended to the mesh */
    double bbox_min[3], bbox_max[3]; /* metres, in the model's frame (Z up, base at the origin) */
    double height;            /* metres */
    double box_dimension;     /* D_B of this model's side silhouette without leaves */
    double law_dimension;     /* D used in eq. 6 for this model; 0 when the law was not used */
    double target_branches;   /* N2 of eq. 6 for this age; 0 when the law was not used */
} sylva_tree_stats;

typedef struct sylva_tree_stats_v1 {
    uint32_t size; /* sizeof(sylva_tree_stats_v1) as the plugin compiled it */
    /* Fills *out with the figures of the model the last successful generate() on `state`
     * built. Returns SYLVA_OK, or SYLVA_ERR_PARAM when none has succeeded yet. */
    int (*last_stats)(void *state, sylva_tree_stats *out);
} sylva_tree_stats_v1;

#ifdef __cplusplus
}
#endif
#endif
