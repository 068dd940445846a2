/* ztv_trace.h — computing a visibility map: for each cell, an observer at eye height above the
 * cell centre's ground; for each target, the sightline between them (ztv/ztv_sight.h) against
 * bare earth and against the screened mode asked for; the cell's count of visible targets, the
 * visible fraction and the developments seen. Rows are computed a block at a time on all the
 * threads and handed, north to south, to a sink (the writers, ztv/ztv_output.h), so memory
 * stays bounded whatever the size of the map. Each cell depends on nothing but the scene and
 * the targets: the result is the same for any thread count.
 *
 * The modes are nested (everything bare earth screens with, the vegetation mode does too, and
 * so on), so a sightline clear of the screened mode's geometry is clear on bare earth too, and
 * one blocked on bare earth is blocked screened: a pair of observer and target costs one
 * sightline or two. Each worker casts first the one that has settled more of its pairs so far
 * (bare earth where the terrain hides most, the screened one where little is screened); the
 * answer is the same in either order. The canopy mode screens with bare earth and the canopy
 * surface, a scene of its own (ztv/ztv_canopy.h): its sightline is cast over the surface only
 * when bare earth leaves it clear.
 */
#ifndef SYLVA_ZTV_TRACE_H
#define SYLVA_ZTV_TRACE_H

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
} ztv_job;

typedef struct ztv_stats {         /* of this part alone */
    uint64_t cells;                 /* computed (within the radius, on the terrain) */
    uint64_t pairs;                 /* cells x targets traced */
    uint64_t rays;                  /* Embree occlusion rays (chords of the sightlines) */
    double seconds;                 /* tracing, the sink's time included */
} ztv_stats;

typedef int (*ztv_sink)(void *user, const ztv_block *b, err_buf *err);

/* Runs job, handing each block to sink(user, ...). Returns 0, or -1 with err set (out of
 * memory, an Embree error, or the sink's own failure). stats may be NULL. */
int ztv_trace(const ztv_job *job, ztv_sink sink, void *user, ztv_stats *stats, err_buf *err);

/* The Embree geometry mask of what screens in mode m (render/accel.h). */
unsigned ztv_mode_mask(ztv_mode m);

#endif
