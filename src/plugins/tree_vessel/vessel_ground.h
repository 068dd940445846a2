/* vessel_ground.h — a tree's hanging branches kept above the ground it stands on. Gravimorphism
 * (3.19, 3.23) arches a weeping tree's limbs over and lets their shoots hang; Algorithm 2 knows
 * no ground, so with 004's weeping willow they hang on through it (its lowest tips 10.9 m below
 * the trunk's foot). A real weeping tree's curtain reaches the ground and its longer shoots
 * trail along it. sylva gives a tree whose hanging tips fall below the clearance c a soft floor: the
 * tip of every segment that points downward, wherever it lies below the knee
 * (VESSEL_GROUND_SOFT above c), is lifted to
 *     z' = c + s (1 − tanh((knee − z) / s)),  s = knee − c,
 * which leaves the knee and the slope there unchanged and approaches c from above however deep
 * the tip would hang; x and y stay. Each segment starts at its mother's new tip (a lateral child
 * at the same offset from it as grown) and runs to its new tip, its frame turned by the least
 * rotation and its length the new distance; segments that point upward keep their direction and
 * length. So the curtain hangs as grown down to the knee and bends out to trail just above the
 * ground. The clearance leaves room for the hanging wood's radius and a leaf beside the axis. A
 * tree whose hanging tips all stay above the clearance is left exactly as grown.
 * docs/models/tree_vessel.md. */
#ifndef VESSEL_GROUND_H
#define VESSEL_GROUND_H

#include "plugin_err.h"
#include "vessel_params.h"
#include "vessel_tree.h"

#define VESSEL_GROUND_GAP 0.1  /* metres between the ground and the lowest leaf or bark */
#define VESSEL_GROUND_SOFT 2.0 /* metres from the clearance up to the knee of the soft floor */

/* The lowest z of the tip of any of t's segments that points downward (+infinity: none does). */
double vessel_lowest_hanging_tip(const vessel_tree *t);

/* How high t's lowest hanging tip must stay: VESSEL_GROUND_GAP plus the largest radius of a
 * downward segment and the largest leaf side of a terminal one. */
double vessel_ground_clearance(const vessel_tree *t, const vessel_params *p);

/* Lifts t onto the soft floor as above when any axis point falls below the clearance. Returns 0,
 * or SYLVA_ERR_NOMEM with err set (t is then unchanged). */
int vessel_hang_above_ground(vessel_tree *t, const vessel_params *p, plugin_err *err);

#endif
