/* ztv_sweep_map.h — a visibility map computed target by target: for each target the bare-earth
 * sweep (ztv/ztv_sweep.h) settles most cells at a few operations each, and the Embree sightline
 * (ztv/ztv_sight.h) decides the cells it leaves in doubt; screening sightlines are cast only for
 * cells that bare earth leaves in sight. The targets are shared out between the threads, each
 * with its own counts, added up when all are done: the maps are the same bytes as the row by row
 * tracer's (ztv/ztv_trace.h) whatever the thread count. The whole map is held in memory (about
 * 20 bytes a cell and 17 more a thread), so it serves maps of up to ZTV_SWEEP_MAX_CELLS cells
 * on a single grid of square cells, without water or cut-out ground, traced in one part.
 */
#ifndef SYLVA_ZTV_SWEEP_MAP_H
#define SYLVA_ZTV_SWEEP_MAP_H

#include <stddef.h>

#include "ztv/ztv_job.h"

#define ZTV_SWEEP_MAX_CELLS (1u << 25)

/* 1 when job's map can be swept; else 0, and why not into why (n bytes; may be NULL). */
int ztv_sweep_map_fits(const ztv_job *job, char *why, size_t n);

/* Runs job as ztv_trace does (same blocks to the sink, same results). */
int ztv_sweep_map(const ztv_job *job, ztv_sink sink, void *user, ztv_stats *stats, err_buf *err);

#endif
