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

#include "ztv/ztv_job.h"

/* Runs job, handing each block to sink(user, ...). Returns 0, or -1 with err set (out of
 * memory, an Embree error, or the sink's own failure). stats may be NULL. */
int ztv_trace(const ztv_job *job, ztv_sink sink, void *user, ztv_stats *stats, err_buf *err);

#endif
