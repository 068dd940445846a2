/* ifs_parallel.h — running numbered tasks on a few threads for one job. Tasks 0..n-1 are handed
 * out from one atomic counter; a task must write only what belongs to it (or to its worker's
 * own buffer), so results never depend on the thread count or on which thread ran what. The
 * calling thread is worker 0 and is the only one that reports progress. */
#ifndef TERRAIN_IFS_PARALLEL_H
#define TERRAIN_IFS_PARALLEL_H

#include <stdint.h>

#define IFS_MAX_THREADS 64u

typedef void (*ifs_task_fn)(void *ctx, uint32_t worker, uint64_t task);
typedef void (*ifs_progress_fn)(void *pctx, uint64_t done, uint64_t total);

/* Runs every task on up to `workers` threads (1..IFS_MAX_THREADS; more are cut to the limit).
 * Returns the number of workers that ran: fewer when thread creation fails, the remaining
 * tasks then run on the threads that exist. progress (may be NULL) is called on the calling
 * thread only. */
uint32_t ifs_parallel_run(uint32_t workers, uint64_t n_tasks, ifs_task_fn fn, void *ctx,
                          ifs_progress_fn progress, void *pctx);

/* Processors online (at least 1, at most IFS_MAX_THREADS). */
uint32_t ifs_online_processors(void);

#endif
