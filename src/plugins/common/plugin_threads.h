/* plugin_threads.h — the plugins' one way to run a job on a few threads: numbered tasks handed
 * out one at a time from an atomic counter (a slow task never leaves a thread idle while others
 * wait), or a loop split into contiguous chunks. The calling thread works too. A task writes only
 * what belongs to it (its slot of an output indexed by task, or its worker's own buffer), so the
 * result never depends on the thread count or on which thread ran what. Plugins include only
 * sylva/plugin.h, so they cannot use the host's own pool (core/util/task_pool). */
#ifndef PLUGIN_THREADS_H
#define PLUGIN_THREADS_H

#include <stddef.h>
#include <stdint.h>

#define PLUGIN_MAX_THREADS 256u

typedef void (*plugin_task_fn)(void *ctx, uint32_t worker, uint64_t task);
typedef void (*plugin_range_fn)(void *ctx, size_t begin, size_t end);
typedef void (*plugin_progress_fn)(void *pctx, uint64_t done, uint64_t total);

/* Runs fn(ctx, worker, task) for every task in [0, n_tasks) on up to `workers` threads (0 and 1
 * both mean the calling thread alone; more than PLUGIN_MAX_THREADS or than n_tasks are cut);
 * worker is in [0, the count returned) and names the thread's own scratch. When a thread cannot
 * be started the others do its share. progress (may be NULL) is called on the calling thread
 * only, between its tasks, and once at the end with done == total. Returns the number of
 * threads that ran. */
uint32_t plugin_threads_run(uint32_t workers, uint64_t n_tasks, plugin_task_fn fn, void *ctx,
                            plugin_progress_fn progress, void *pctx);

/* Runs fn over [0, n) split into one contiguous chunk per thread, on up to `workers` threads. */
void plugin_threads_for(uint32_t workers, size_t n, plugin_range_fn fn, void *ctx);

/* Processors online (at least 1, at most PLUGIN_MAX_THREADS). */
uint32_t plugin_threads_online(void);

#endif
