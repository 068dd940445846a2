/* aono_stats.h — what one Aono–Kunii tree is, as `sylva tree-stats` prints it for every tree
 * plugin (sylva_tree_stats): the levels grown, the branch segments, the axes (the trunk and
 * every branch that does not continue its mother), the leaves, the mesh's triangles and bounds,
 * and the box-counting dimension D_B of the wood's side silhouette (002 eq. 3, box_count.h),
 * measured as every tree plugin measures it. */
#ifndef AONO_STATS_H
#define AONO_STATS_H

#include "aono_grow.h"
#include "aono_mesh_buffer.h"
#include "sylva/plugin.h"
#include "sylva/tree_stats.h"

/* Fills *st (its size and age left as the caller set them) from the skeleton s and the mesh b
 * built from it, whose leaf triangles have material `leaf`. Returns 0, or -1 when memory for the
 * silhouette raster runs out (st then has D_B 0 and every other figure). */
int aono_stats_measure(const aono_skeleton *s, const aono_mesh_buffer *b, int32_t leaf, sylva_tree_stats *st);

#endif
