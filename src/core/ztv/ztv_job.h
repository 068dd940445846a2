/* ztv_job.h — what a visibility map's computation is asked (the scene, its Embree scene, the
 * targets, the grid, the observer, the screening, the threads) and what it reports; the blocks of
 * rows it hands on go to a sink (ztv/ztv_trace.h runs a job). */
#ifndef SYLVA_ZTV_JOB_H
#define SYLVA_ZTV_JOB_H

#include <stdint.h>

#include "render/accel.h"
#include "scene/scene.h"
#include "util/err.h"
#include "ztv/ztv_raster.h"
#include "ztv/ztv_targets.h"

#define ZTV_BLOCK_CELLS (1u << 18) /* cells per block handed to the sink (whole rows; at least one) */

typedef struct ztv_job {
    const scene *scene;
    const accel *accel;             /* built from scene */
    const ztv_targets *targets;
    ztv_grid grid;
    double observer_height;         /* metres above the ground */
    double radius;                  /* metres from the nearest target; INFINITY: every cell */
    ztv_mode screened;              /* ZTV_BARE: bare earth alone */
    const earth_settings *earth;    /* NULL: a flat Earth */
    unsigned threads;               /* 0: one per core */
    int quiet;                      /* 1: no progress on stderr */
    uint32_t part, parts;           /* parts > 1: compute only the rows j with j % parts == part
                                     * (one rank of an MPI job, docs/mpi.md); a block's other
                                     * rows are left undefined. 0 or 1: every row */
    int sightlines;                 /* 1: every pair by its sightline, bare earth too (the
                                     * reference the bare-earth sweep is checked against) */
} ztv_job;

typedef struct ztv_stats {         /* of this part alone */
    uint64_t cells;                 /* computed (within the radius, on the terrain) */
    uint64_t pairs;                 /* cells x targets traced */
    uint64_t rays;                  /* Embree occlusion rays (chords of the sightlines) */
    uint64_t swept;                 /* pairs the bare-earth sweep settled without a sightline */
    double seconds;                 /* tracing, the sink's time included */
} ztv_stats;

typedef int (*ztv_sink)(void *user, const ztv_block *b, err_buf *err);

/* The Embree geometry mask of what screens in mode m (render/accel.h). */
static inline unsigned ztv_mode_mask(ztv_mode m)
{
    switch (m) {
    case ZTV_BARE: return ACCEL_MASK_GROUND;
    case ZTV_VEGETATION: return ACCEL_MASK_GROUND | ACCEL_MASK_PLANT;
    case ZTV_CANOPY: return ACCEL_MASK_GROUND; /* and the canopy surface's own scene (ztv_canopy.h) */
    default: return ACCEL_MASK_GROUND | ACCEL_MASK_PLANT | ACCEL_MASK_OBJECT;
    }
}

#endif
