/* vessel_stats.h — what one vessel tree is, as `sylva tree-stats` prints it for every tree
 * plugin (sylva_tree_stats): the depth of Algorithm 2's recursion, the wood segments drawn, the
 * axes that carry wood, the leaves, the mesh's triangles and bounds, and the box-counting
 * dimension D_B of the wood's side silhouette (002 eq. 3, box_count.h), measured as every tree
 * plugin measures it. */
#ifndef VESSEL_STATS_H
#define VESSEL_STATS_H

#include "sylva/plugin.h"
#include "sylva/tree_stats.h"
#include "vessel_mesh.h"
#include "vessel_structure.h"

/* Fills *st (its size and age left as the caller set them) from the structure t and the mesh m
 * built from it. Returns 0, or -1 when memory for the silhouette raster runs out (st then has
 * D_B 0 and every other figure). */
int vessel_stats_measure(const vessel_tree *t, const vessel_mesh *m, sylva_tree_stats *st);

#endif
