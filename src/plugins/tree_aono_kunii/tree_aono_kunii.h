/* tree_aono_kunii.h — the tree_aono_kunii descriptor: create() reads and checks the parameters and
 * makes the bark and leaf materials (and the leaf texture); generate() grows one age variant
 * and appends its mesh; destroy() frees the state. The module's entry point returns it, and
 * tests and benchmarks call it directly through a host of their own.
 */
#ifndef TREE_AONO_KUNII_H
#define TREE_AONO_KUNII_H

#include <stdint.h>

#include "sylva/plugin.h"

/* The descriptor (static const data). */
const sylva_plugin *aono_plugin(void);

/* Branching levels of the variant of normalised age `age` in (0, 1] for a full-grown tree of
 * `levels`: ceil(age levels), at least 1. */
uint32_t aono_variant_levels(uint32_t levels, double age);

#endif
