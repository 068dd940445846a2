/* wp_stats.h — the figures of one tree_weber_penn model for `sylva tree-stats`
 * (sylva.tree_stats.v1): recursion = the stem levels grown, segments = Arbaro's stem faces
 * (the OBJ faces of the trunk and stem groups, as Arbaro counts them), branches = the stems
 * grown (trunk and clones included), leaves, the triangles handed to the host, their bounds and
 * top, and D_B of the stems' side silhouette (every stem triangle filled onto the shared
 * silhouette raster, box_count.h; leaves left out). */
#ifndef WP_STATS_H
#define WP_STATS_H

#include "sylva/tree_stats.h"
#include "wp_host_mesh.h"
#include "wp_model.h"

/* Fills st's figures (its size and age are the caller's) from the model grown with `levels`
 * stem levels and the mesh made of it. Returns 0, or -1 when memory runs out for the silhouette. */
int wp_stats_measure(const wp_model *m, int levels, const wp_host_mesh *w, sylva_tree_stats *st);

#endif
