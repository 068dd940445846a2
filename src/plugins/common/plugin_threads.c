/* plugin_threads.c — numbered tasks or contiguous chunks of a loop on pthreads. */
#include "plugin_threads.h"

#include <pthread.h>
#include <stdatomic.h>
#include <unistd.h>

typedef struct threads_job {
    plugin_task_fn fn;
    void *ctx;
    uint64_t n_tasks;
    atomic_uint_fast64_t next; /* the next task to hand out */
    atomic_uint_fast64_t done; /* tasks finished */
} threads_job;

typedef struct threads_worker {
    threads_job *job;
    uint32_t index;
    pthread_t thread;
} threads_worker;

/* Takes tasks until none is left; returns the count finished (by anyone) after its last task. */
static uint64_t work(threads_job *job, uint32_t worker, plugin_progress_fn progress, void *pctx)
{
    uint64_t done = 0;
    for (uint64_t t; (t = atomic_fetch_add(&job->next, 1)) < job->n_tasks;) {
        job->fn(job->ctx, worker, t);
        done = atomic_fetch_add(&job->done, 1) + 1;
        if (progress) progress(pctx, done, job->n_tasks);
    }
    return done;
}

static void *worker_main(void *arg)
{
    threads_worker *w = arg;
    work(w->job, w->index, NULL, NULL);
    return NULL;
}

uint32_t plugin_threads_run(uint32_t workers, uint64_t n_tasks, plugin_task_fn fn, void *ctx,
                            plugin_progress_fn progress, void *pctx)
{
    if (workers > PLUGIN_MAX_THREADS) workers = PLUGIN_MAX_THREADS;
    if (workers > n_tasks) workers = (uint32_t)n_tasks;
    if (workers < 1) workers = 1;
    threads_job job = {.fn = fn, .ctx = ctx, .n_tasks = n_tasks};
    atomic_init(&job.next, 0);
    atomic_init(&job.done, 0);
    threads_worker w[PLUGIN_MAX_THREADS];
    uint32_t started = 1;
    for (; started < workers; started++) {
        w[started] = (threads_worker){.job = &job, .index = started};
        if (pthread_create(&w[started].thread, NULL, worker_main, &w[started])) break;
    }
    /* the calling thread is worker 0: it finishes what a thread that did not start left */
    uint64_t reported = work(&job, 0, progress, pctx);
    for (uint32_t k = 1; k < started; k++) pthread_join(w[k].thread, NULL);
    if (progress && reported < n_tasks) progress(pctx, n_tasks, n_tasks);
    return started;
}

typedef struct threads_chunks {
    plugin_range_fn fn;
    void *ctx;
    size_t n, chunks;
} threads_chunks;

static void chunk_task(void *ctx, uint32_t worker, uint64_t task)
{
    (void)worker;
    const threads_chunks *c = ctx;
    c->fn(c->ctx, c->n * task / c->chunks, c->n * (task + 1) / c->chunks);
}

void plugin_threads_for(uint32_t workers, size_t n, plugin_range_fn fn, void *ctx)
{
    if (workers > PLUGIN_MAX_THREADS) workers = PLUGIN_MAX_THREADS;
    if (workers > n) workers = (uint32_t)n;
    if (workers <= 1) {
        if (n) fn(ctx, 0, n);
        return;
    }
    threads_chunks c = {.fn = fn, .ctx = ctx, .n = n, .chunks = workers};
    plugin_threads_run(workers, workers, chunk_task, &c, NULL, NULL);
}

uint32_t plugin_threads_online(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    if (n < 1) n = 1;
    if (n > (long)PLUGIN_MAX_THREADS) n = PLUGIN_MAX_THREADS;
    return (uint32_t)n;
}
