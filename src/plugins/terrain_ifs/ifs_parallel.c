/* ifs_parallel.c — a one-job thread pool on pthreads. */
#include "ifs_parallel.h"

#include <pthread.h>
#include <stdatomic.h>
#include <unistd.h>

typedef struct parallel_job {
    ifs_task_fn fn;
    void *ctx;
    uint64_t n_tasks;
    atomic_uint_fast64_t next;  /* next task to hand out */
    atomic_uint_fast64_t done;  /* tasks finished */
} parallel_job;

typedef struct parallel_worker {
    parallel_job *job;
    uint32_t index;
    pthread_t thread;
} parallel_worker;

static void *worker_main(void *arg)
{
    parallel_worker *w = arg;
    parallel_job *job = w->job;
    for (;;) {
        uint64_t t = atomic_fetch_add(&job->next, 1);
        if (t >= job->n_tasks) break;
        job->fn(job->ctx, w->index, t);
        atomic_fetch_add(&job->done, 1);
    }
    return NULL;
}

uint32_t ifs_parallel_run(uint32_t workers, uint64_t n_tasks, ifs_task_fn fn, void *ctx,
                          ifs_progress_fn progress, void *pctx)
{
    if (workers < 1) workers = 1;
    if (workers > IFS_MAX_THREADS) workers = IFS_MAX_THREADS;
    if (workers > n_tasks) workers = n_tasks ? (uint32_t)n_tasks : 1;
    parallel_job job = {.fn = fn, .ctx = ctx, .n_tasks = n_tasks};
    atomic_init(&job.next, 0);
    atomic_init(&job.done, 0);
    parallel_worker w[IFS_MAX_THREADS];
    uint32_t started = 1;
    for (uint32_t k = 1; k < workers; k++) {
        w[k] = (parallel_worker){.job = &job, .index = k};
        if (pthread_create(&w[k].thread, NULL, worker_main, &w[k])) break;
        started++;
    }
    /* The calling thread works as worker 0 and reports progress between its tasks. */
    uint64_t reported = 0;
    for (;;) {
        uint64_t t = atomic_fetch_add(&job.next, 1);
        if (t >= n_tasks) break;
        fn(ctx, 0, t);
        reported = atomic_fetch_add(&job.done, 1) + 1;
        if (progress) progress(pctx, reported, n_tasks);
    }
    for (uint32_t k = 1; k < started; k++) pthread_join(w[k].thread, NULL);
    if (progress && reported < n_tasks) progress(pctx, n_tasks, n_tasks);
    return started;
}

uint32_t ifs_online_processors(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    if (n < 1) n = 1;
    if (n > (long)IFS_MAX_THREADS) n = IFS_MAX_THREADS;
    return (uint32_t)n;
}
