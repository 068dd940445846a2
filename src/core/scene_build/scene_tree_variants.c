/* scene_tree_variants.c — a species' variants made in parallel, kept in index order
 * (scene_tree_variants.h). */
#include "scene_build/scene_tree_variants.h"

#include <stdlib.h>

#include "util/task_pool.h"

typedef struct variant_job {
    plugin_call **callers; /* per thread: a share of the plugin call, or the call itself */
    tree_variant *tv;      /* per variant */
    mesh **meshes;         /* per variant; owned here until the scene takes them */
    err_buf *errs;         /* per variant */
    int *rc;               /* per variant */
    uint32_t count;
    int concurrent;        /* 0: one thread, variants in order, none after a failure */
    int failed;
} variant_job;

/* Concurrent, the largest variant (the full-grown tree, the last) first, so that no thread is
 * left with it at the end while the others wait; one at a time, in index order as before. */
static void make_variant(void *ctx, unsigned worker, uint32_t i)
{
    variant_job *job = ctx;
    uint32_t v = job->concurrent ? job->count - 1 - i : i;
    if (job->failed) return; /* set only when one thread runs them all */
    job->tv[v] = (tree_variant){.index = v, .count = job->count};
    job->meshes[v] = mesh_new();
    if (!job->meshes[v]) job->rc[v] = err_nomem(&job->errs[v], "out of memory");
    else job->rc[v] = plugin_call_tree(job->callers[worker], &job->tv[v], job->meshes[v], &job->errs[v]);
    if (job->rc[v] && !job->concurrent) job->failed = 1;
}

int tree_variants_build(plugin_call *c, scene *s, uint32_t sp, uint32_t count, unsigned threads,
                        err_buf *err)
{
    if (!count) return 0;
    int concurrent = plugin_call_concurrent(c);
    if (!threads) threads = task_pool_default_threads();
    if (!concurrent || threads > count) threads = concurrent ? count : 1;
    variant_job job = {.count = count, .concurrent = concurrent};
    plugin_call *shares = concurrent ? calloc(threads, sizeof *shares) : NULL; /* owned here */
    job.callers = calloc(threads, sizeof *job.callers);
    job.tv = calloc(count, sizeof *job.tv);
    job.meshes = calloc(count, sizeof *job.meshes);
    job.errs = calloc(count, sizeof *job.errs);
    job.rc = calloc(count, sizeof *job.rc);
    int rc = 0;
    if ((concurrent && !shares) || !job.callers || !job.tv || !job.meshes || !job.errs || !job.rc) {
        rc = err_nomem(err, "out of memory for %u tree variants", count);
        goto done;
    }
    for (unsigned w = 0; w < threads; w++) {
        if (concurrent) plugin_call_share(c, &shares[w]);
        job.callers[w] = concurrent ? &shares[w] : c;
    }
    task_pool_run(threads, count, make_variant, &job);
    for (unsigned w = 0; concurrent && w < threads; w++) plugin_call_unshare(&shares[w]);
    for (uint32_t v = 0; v < count && !rc; v++) {
        if (job.rc[v]) {
            *err = job.errs[v];
            rc = -1;
        } else {
            mesh *m = job.meshes[v];
            job.meshes[v] = NULL; /* the scene's now, even when adding fails */
            if (scene_add_prototype(s, sp, v, job.tv[v].age, job.tv[v].height, m, err) < 0) rc = -1;
            else s->species[sp].n_variants++;
        }
    }
done:
    for (uint32_t v = 0; job.meshes && v < count; v++) mesh_free(job.meshes[v]);
    free(shares), free(job.callers), free(job.tv), free(job.meshes), free(job.errs), free(job.rc);
    return rc;
}
