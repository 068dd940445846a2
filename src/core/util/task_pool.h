/* task_pool.h — numbered tasks on a few threads for one job. Tasks 0..n-1 are handed out one at
 * a time from an atomic counter, so a slow task never leaves a thread idle while others wait;
 * the calling thread works too. A task writes only what belongs to it (its slot of an array
 * indexed by task), so the result never depends on the thread count or on which thread ran
 * which task. */
#ifndef SYLVA_TASK_POOL_H
#define SYLVA_TASK_POOL_H

#include <stdint.h>

/* Runs task(ctx, worker, i) for every i in [0, n) on up to `threads` threads (0: one per
 * processor; never more than n). worker is in [0, threads) and names the thread's own scratch,
 * if any. When a thread cannot be started the others do its share. Returns the number of
 * threads that ran. */
unsigned task_pool_run(unsigned threads, uint32_t n, void (*task)(void *ctx, unsigned worker, uint32_t i),
                       void *ctx);

/* Processors online (at least 1): the thread count that 0 stands for. */
unsigned task_pool_default_threads(void);

#endif
