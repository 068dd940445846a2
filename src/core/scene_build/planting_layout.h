/* planting_layout.h — where the plants of a planting plan stand: a block's square grid inside
 * its polygon, a belt's staggered rows along its line, a tree at its point; each plant's
 * species (a block's mix by its shares, a belt's sequence in order), turn, stock height within
 * its size's range and thinning rank, all from the plan's seed and the plant's place in its
 * feature, never from the year: the same plants stand in the same places whatever the year
 * (docs/mitigation.md, "Where the plants stand").
 *
 * Ownership: planting_layout_new returns an array the caller frees with free(). */
#ifndef SYLVA_PLANTING_LAYOUT_H
#define SYLVA_PLANTING_LAYOUT_H

#include <stdint.h>

#include "scene_file/scene_file_spec.h"
#include "util/err.h"

typedef struct planted_plant {
    uint32_t feature;           /* index into the plan's features */
    uint32_t species;           /* scene-file species index */
    double xy[2];               /* local metres */
    double rotation_deg;        /* about +Z */
    double stock_height;        /* metres at planting */
    double thinning_rank;       /* in [0, 1): thinned when at least the share kept */
} planted_plant;

/* The plants of every block, belt and tree of plan, in the plan's order (feature by feature, a
 * block's row by row from the south-west, a belt's row by row along its line). Returns the
 * array (*n plants, possibly 0), or NULL with err set when out of memory or when a feature
 * would hold more than max_plants plants in all. */
planted_plant *planting_layout_new(const planting_spec *plan, uint64_t max_plants, uint32_t *n, err_buf *err);

/* 1 when (x, y) lies inside the ring xy (even-odd rule). */
int planting_ring_contains(const double (*xy)[2], uint32_t n, double x, double y);

#endif
