/* aono_ratio.c — contraction ratios from the tree's height H, first-branch height H0 and crown
 * diameter L: equations (23) and (24) of seed 000 and their ternary form. */
#include "aono_ratio.h"

#include <stdio.h>

int aono_ratios_from_dimensions(aono_pattern pattern, uint32_t lvt, double height, double trunk_length,
                                double crown_diameter, double rko, double r[AONO_MAX_CHILDREN], char *why,
                                size_t why_size)
{
    double H = height, H0 = trunk_length, L = crown_diameter;
    if (!(H0 < H)) {
        snprintf(why, why_size, "ri_method dimensions takes R1 = 1 - H0/H (23), which is a contraction "
                                "ratio in (0, 1) only when the trunk length H0 = %g m is below the height "
                                "H = %g m",
                 H0, H);
        return -1;
    }
    double axis = 1.0 - H0 / H; /* (23) */
    switch (pattern) {
    case AONO_DICHOTOMOUS:
        r[0] = axis;
        r[1] = rko * axis;
        r[2] = 0.0;
        return 0;
    case AONO_MONOPODIAL: {
        double h = H - H0, lateral = L / h * axis; /* (24) */
        if (!(lateral < 1.0)) {
            snprintf(why, why_size, "ri_method dimensions gives the lateral ratio R2 = (L/h) R1 = (%g / %g) x "
                                    "%g = %g (24), but a contraction ratio must be below 1: make the crown "
                                    "diameter L smaller than h / R1 = %g m",
                     L, h, axis, lateral, h / axis);
            return -1;
        }
        r[lvt] = axis;
        r[1 - lvt] = lateral;
        r[2] = 0.0;
        return 0;
    }
    default: {
        double lateral = L / H * axis; /* ternary: R1 = R2 = (L/H) R3 */
        if (!(lateral < 1.0)) {
            snprintf(why, why_size, "ri_method dimensions gives the lateral ratios R1 = R2 = (L/H) R3 = "
                                    "(%g / %g) x %g = %g, but a contraction ratio must be below 1: make the "
                                    "crown diameter L smaller than H / R3 = %g m",
                     L, H, axis, lateral, H / axis);
            return -1;
        }
        r[0] = r[1] = lateral;
        r[2] = axis;
        return 0;
    }
    }
}
