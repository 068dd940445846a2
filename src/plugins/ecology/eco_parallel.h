/* eco_parallel.h — splitting a loop over [0, n) into contiguous chunks run on worker threads.
 * Every item must write only its own output, so the result never depends on the thread count. */
#ifndef ECO_PARALLEL_H
#define ECO_PARALLEL_H

#include <stddef.h>

typedef void (*eco_range_fn)(void *ctx, size_t begin, size_t end);

/* Runs fn over [0, n) on up to `threads` threads (the caller's thread is one of them); falls
 * back to running everything on the caller's thread when a thread cannot be started. */
void eco_parallel_for(unsigned threads, size_t n, eco_range_fn fn, void *ctx);

/* The number of online processors (at least 1). */
unsigned eco_cpu_count(void);

#endif
