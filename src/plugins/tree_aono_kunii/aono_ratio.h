/* aono_ratio.h — contraction ratios R_i from the tree's dimensions, method (2) of seed 000
 * §3.2: R1 = 1 − H0/H (23) and R2 = (L/h) R1 with h = H − H0 (24) for a main axis
 * (monopodial); R2 = RKO R1 for dichotomous branching; R3 = 1 − H0/H and R1 = R2 = (L/H) R3 for
 * three children (ternary and stochastic). A child's length is ρ_i = R_i ρ_op. Pure functions.
 */
#ifndef AONO_RATIO_H
#define AONO_RATIO_H

#include <stddef.h>
#include <stdint.h>

#include "aono_pattern.h"

/* Fills r[0..2] for `pattern` (lvt: the continuing child of a monopodial branching, 0 or 1).
 * Returns 0, or -1 with a sentence in why[] when a ratio is not in (0, 1) — which it must be
 * for the series (20) to converge — naming the dimension to change and the bound it has. */
int aono_ratios_from_dimensions(aono_pattern pattern, uint32_t lvt, double height, double trunk_length,
                                double crown_diameter, double rko, double r[AONO_MAX_CHILDREN], char *why,
                                size_t why_size);

#endif
