/* vessel_leaves.h — where the leaves of one terminal branch go (004 §3.3.2, Figs. 3.15–3.19).
 * A terminal branch bears rho_l leaves of size l_l, each a square quad (side sqrt(2) l_l)
 * growing outward from the branch; with an odd count one leaf sits on the tip, pointing along the branch; the others
 * follow the distribution:
 *   stacked     pairs, one leaf on each side, every pair in the branch's x-y plane;
 *   staggered   one leaf per place, sides alternating, in the x-y plane;
 *   spiral      one leaf per place, each turned about the branch by the phyllotaxis angle;
 *   bunched     all at the tip, spread evenly about the branch;
 *   coniferous  as staggered, at 45 degrees to the branch, leaning toward its tip.
 * Places along the branch are evenly spaced, leaving out the base and the tip. */
#ifndef VESSEL_LEAVES_H
#define VESSEL_LEAVES_H

#include <stdint.h>

#include "vessel_math.h"
#include "vessel_params.h"
#include "vessel_tree.h"

#define VESSEL_CONIFEROUS_ANGLE 45.0 /* degrees between a coniferous leaf and its branch */
/* Stacked, staggered and coniferous leaves on one side of a branch would all lie in one plane and
 * overlap there (coincident alpha-masked quads, which renderers resolve differently); each
 * further pair turns this many degrees about the branch so no two share a plane. */
#define VESSEL_LEAF_TWIST 7.0
/* A leaf of size l_l is a square of half-diagonal l_l, as 004 draws it (a four-sided disc of
 * radius l_l, Fig. C.8): its side is sqrt(2) l_l. */
#define VESSEL_LEAF_SIDE_PER_SIZE M_SQRT2

/* One leaf quad: the middle of its stalk edge, the unit direction it grows in, the unit
 * direction across its blade, and its side length (sqrt(2) l_l). Corners: base -/+ across size/2, and the
 * same moved by out * size. */
typedef struct vessel_leaf {
    vessel_vec base, out, across;
    double size;
} vessel_leaf;

/* Where one leaf goes on any terminal branch, in the branch's local frame: the fraction of the
 * length where its stalk sits, and its unit outward and across directions. */
typedef struct vessel_leaf_slot {
    double along;
    vessel_vec out, across;
} vessel_leaf_slot;

/* Writes the rho_l slots of p's distribution into slots[0 .. rho_l) and returns rho_l. The
 * layout is the same on every terminal branch, so a mesh computes it once. */
uint32_t vessel_leaf_layout(const vessel_params *p, vessel_leaf_slot *slots);

/* Side of the leaves on terminal branch b. A branch cut short by the level of detail stands for
 * its S0 vessels: its leaves are sqrt(S0) times larger, so they cover the same area as the S0
 * branches' leaves would. */
double vessel_leaf_side(const vessel_branch *b, const vessel_params *p);

/* The leaf of slot s on branch b, in the tree's frame. */
vessel_leaf vessel_leaf_on(const vessel_branch *b, const vessel_leaf_slot *s, double side);

/* Writes the leaves of terminal branch b into out[0 .. rho_l) and returns rho_l. */
uint32_t vessel_leaves_place(const vessel_branch *b, const vessel_params *p, vessel_leaf *out);

#endif
