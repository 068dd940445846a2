/* task_pool.c — a one-job pool of pthreads fed from an atomic counter (task_pool.h). */
#include "util/task_pool.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <unistd.h>

typedef struct pool_job {
    void (*task)(void *ctx, unsigned worker, uint32_t i);
    void *ctx;
    uint32_t n;
    atomic_uint next;
} pool_job;

typedef struct pool_worker {
    pool_job *job;
    unsigned index;
} pool_worker;

static void *pool_work(void *arg)
{
    pool_worker *w = arg;
    pool_job *job = w->job;
    for (;;) {
        unsigned i = atomic_fetch_add(&job->next, 1u);
        if (i >= job->n) break;
        job->task(job->ctx, w->index, i);
    }
    return NULL;
}

unsigned task_pool_default_threads(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n > 0 ? (unsigned)n : 1u;
}

unsigned task_pool_run(unsigned threads, uint32_t n, void (*task)(void *ctx, unsigned worker, uint32_t i),
                       void *ctx)
{
    if (!threads) threads = task_pool_default_threads();
    if (threads > n) threads = n ? n : 1;
    pool_job job = {.task = task, .ctx = ctx, .n = n};
    atomic_init(&job.next, 0u);
    pool_worker *w = threads > 1 ? calloc(threads, sizeof *w) : NULL;        /* owned here */
    pthread_t *tid = threads > 1 ? calloc(threads, sizeof *tid) : NULL;      /* owned here */
    unsigned started = 1;
    if (w && tid)
        for (; started < threads; started++) {
            w[started] = (pool_worker){&job, started};
            if (pthread_create(&tid[started], NULL, pool_work, &w[started])) break;
        }
    pool_worker self = {&job, 0};
    pool_work(&self);
    for (unsigned k = 1; k < started; k++) pthread_join(tid[k], NULL);
    free(w);
    free(tid);
    return started;
}
