/* ztv_fixture.h — a visibility map of a built scene traced in a test: the scene's targets, its
 * BVH, one cell per terrain node, every block of rows handed to the test's callback. */
#ifndef SYLVA_TEST_ZTV_FIXTURE_H
#define SYLVA_TEST_ZTV_FIXTURE_H

#include <math.h>

#include "render/accel.h"
#include "ztv/ztv_grid.h"
#include "ztv/ztv_targets.h"
#include "ztv/ztv_trace.h"

/* Traces s (built from sf) in mode on threads threads, observers 2 m up over the whole terrain;
 * *grid receives the map's grid before the first block (on_grid, when not NULL, is called with it
 * then). Returns 0, or -1 with err set. */
static inline int ztv_fixture_trace(const scene_file *sf, const scene *s, ztv_mode mode, unsigned threads,
                                    void (*on_grid)(void *user, const ztv_grid *g),
                                    int (*block)(void *user, const ztv_block *b, err_buf *err), void *user,
                                    err_buf *err)
{
    ztv_targets t;
    accel a;
    if (ztv_targets_build(&t, sf, s, 1, err)) return -1;
    if (accel_build(&a, s, threads, err)) {
        ztv_targets_free(&t);
        return -1;
    }
    ztv_job job = {.scene = s, .accel = &a, .targets = &t, .observer_height = 2, .radius = INFINITY,
                   .screened = mode, .threads = threads, .quiet = 1};
    int rc = ztv_grid_make(s, &t, 0, INFINITY, &job.grid, err);
    if (!rc && on_grid) on_grid(user, &job.grid);
    if (!rc) rc = ztv_trace(&job, block, user, NULL, err);
    accel_free(&a);
    ztv_targets_free(&t);
    return rc;
}

#endif
