/* eco_parallel.h — splitting a loop over [0, n) into contiguous chunks, or handing out its items
 * one at a time, on worker threads.
 * Every item must write only its own output, so the result never depends on the thread count. */
#ifndef ECO_PARALLEL_H
#define ECO_PARALLEL_H

#include <stddef.h>

typedef void (*eco_range_fn)(void *ctx, size_t begin, size_t end);

/* Runs fn over [0, n) on up to `threads` threads (the caller's thread is one of them); falls
 * back to running everything on the caller's thread when a thread cannot be started. */
void eco_parallel_for(unsigned threads, size_t n, eco_range_fn fn, void *ctx);

typedef void (*eco_item_fn)(void *ctx, size_t i);

/* Runs fn(ctx, i) for every i in [0, n) on up to `threads` threads, handing the items out one
 * at a time (for a few items of unequal work, such as the species). Each item writes only its
 * own output. */
void eco_parallel_each(unsigned threads, size_t n, eco_item_fn fn, void *ctx);

/* The number of online processors (at least 1). */
unsigned eco_cpu_count(void);

#endif
