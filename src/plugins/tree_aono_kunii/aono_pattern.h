/* aono_pattern.h — the branching patterns of seed 000 §3.1 (how many children a branching has
 * and which continues the mother) and the most children one branching has. Header-only. */
#ifndef AONO_PATTERN_H
#define AONO_PATTERN_H

#define AONO_MAX_CHILDREN 3

typedef enum aono_pattern {
    AONO_DICHOTOMOUS = 0, /* two children, both at their angle FI */
    AONO_MONOPODIAL = 1,  /* two children; child LVT continues the mother's direction */
    AONO_TERNARY = 2,     /* three children; the third is the middle one */
    AONO_STOCHASTIC = 3   /* two or three children, three with a given probability */
} aono_pattern;

#endif
