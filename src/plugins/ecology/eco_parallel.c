/* eco_parallel.c — contiguous chunks of a loop, or its items one at a time, on pthreads. */
#include "eco_parallel.h"

#include <pthread.h>
#include <stdatomic.h>
#include <unistd.h>

#define ECO_MAX_THREADS 256

typedef struct eco_chunk {
    eco_range_fn fn;
    void *ctx;
    size_t begin, end;
} eco_chunk;

static void *eco_chunk_run(void *arg)
{
    eco_chunk *c = arg;
    c->fn(c->ctx, c->begin, c->end);
    return NULL;
}

void eco_parallel_for(unsigned threads, size_t n, eco_range_fn fn, void *ctx)
{
    if (threads > ECO_MAX_THREADS) threads = ECO_MAX_THREADS;
    if (threads > n) threads = (unsigned)n;
    if (threads <= 1) {
        if (n) fn(ctx, 0, n);
        return;
    }
    eco_chunk chunk[ECO_MAX_THREADS];
    pthread_t tid[ECO_MAX_THREADS];
    int started[ECO_MAX_THREADS] = {0};
    for (unsigned t = 0; t < threads; t++)
        chunk[t] = (eco_chunk){fn, ctx, n * t / threads, n * (t + 1) / threads};
    for (unsigned t = 1; t < threads; t++) started[t] = !pthread_create(&tid[t], NULL, eco_chunk_run, &chunk[t]);
    eco_chunk_run(&chunk[0]);
    for (unsigned t = 1; t < threads; t++) {
        if (started[t]) pthread_join(tid[t], NULL);
        else eco_chunk_run(&chunk[t]);
    }
}

typedef struct eco_items {
    eco_item_fn fn;
    void *ctx;
    size_t n;
    atomic_size_t next;
} eco_items;

static void *eco_items_run(void *arg)
{
    eco_items *it = arg;
    for (size_t i; (i = atomic_fetch_add(&it->next, 1)) < it->n;) it->fn(it->ctx, i);
    return NULL;
}

void eco_parallel_each(unsigned threads, size_t n, eco_item_fn fn, void *ctx)
{
    if (threads > ECO_MAX_THREADS) threads = ECO_MAX_THREADS;
    if (threads > n) threads = (unsigned)n;
    eco_items it = {.fn = fn, .ctx = ctx, .n = n};
    atomic_init(&it.next, 0);
    pthread_t tid[ECO_MAX_THREADS];
    unsigned started = 1;
    for (; started < threads; started++)
        if (pthread_create(&tid[started], NULL, eco_items_run, &it)) break;
    eco_items_run(&it); /* the caller works too, and finishes what a thread that did not start left */
    for (unsigned t = 1; t < started; t++) pthread_join(tid[t], NULL);
}

unsigned eco_cpu_count(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n < 1 ? 1u : n > ECO_MAX_THREADS ? ECO_MAX_THREADS : (unsigned)n;
}
