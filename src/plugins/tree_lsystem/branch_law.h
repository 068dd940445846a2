/* branch_law.h — the extended fractal square-root law of 002: a tree of height H1 with N1
 * branches has N2 = N1 (H1 / H2)^(-D/2) branches at height H2 (002 eq. 6), D being the
 * box-counting dimension of its silhouette (eq. 3, box_count.h). Used to pick the recursion
 * level whose branch count matches a younger (or older) tree.
 *
 * A branch here is an axis that carries wood: the main axis when the string draws a segment
 * outside every bracket, and each `[ ]` block that draws a segment (F or Z) itself — wood in a
 * block nested inside it is that block's branch.
 */
#ifndef BRANCH_LAW_H
#define BRANCH_LAW_H

#include <stddef.h>
#include <stdint.h>

#include "lsys_status.h"

/* 002 eq. 6. h1, h2 > 0. */
double branch_law_count(double n1, double h1, double h2, double d);

/* Branches of a derived string (see above) in *count. Argument groups are skipped. Returns
 * LSYS_OK, or LSYS_ERR_NOMEM (sentence in err, *count 0) when the bracket stack cannot grow. */
int branch_count(const unsigned char *s, size_t n, uint64_t *count, plugin_err *err);

/* The level in [0, levels) whose branch count is nearest to `target` on a logarithmic scale;
 * of equally near levels the highest wins. Levels with no branches are never nearer than one
 * with some (log 0 is -infinity) unless all have none. */
uint32_t branch_law_level(const uint64_t *branches, uint32_t levels, double target);

#endif
