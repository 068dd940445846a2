/* test_scene_estimate.c — the memory estimate of a scene's objects against what building them
 * really takes: a layout of 100,000 boxes of one size is loaded, built and put into the
 * renderer's BVH, and the growth of the process's peak resident memory is compared with the
 * estimate the loader checks (found through SYLVA_MEMORY_LIMIT: a limit under the estimate
 * refuses the scene, one above it lets it through). The estimate must not fall short of what is
 * allocated, nor be far above it. */
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>

#include "harness.h"
#include "work_dir.h"
#include "render/accel.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"

#define BOXES 100000

static uint64_t peak_bytes(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return (uint64_t)ru.ru_maxrss * 1024;
}

/* 1 when the scene loads under SYLVA_MEMORY_LIMIT = limit bytes; a refusal must be the
 * estimate's. */
static int loads_within(const char *path, uint64_t limit)
{
    char text[32];
    snprintf(text, sizeof text, "%llu", (unsigned long long)limit);
    setenv("SYLVA_MEMORY_LIMIT", text, 1);
    err_buf err = {{0}};
    scene_file *sf = scene_file_load(path, NULL, &err);
    unsetenv("SYLVA_MEMORY_LIMIT");
    if (!sf) CHECK_STR_CONTAINS(err.msg, "100000 placements of objects");
    scene_file_free(sf);
    return sf != NULL;
}

TEST(boxes_estimate_what_they_take)
{
    FILE *f = fopen(work_path("boxes.csv"), "w");
    CHECK(f != NULL);
    if (!f) return;
    fputs("id,x,y\n", f);
    for (int k = 0; k < BOXES; k++) fprintf(f, "b%d,%d,%d\n", k, -990 + 2 * (k % 990), -990 + 2 * (k / 990));
    fclose(f);
    const char *path = work_file("boxes.yaml",
                                 "camera: {position: [0, -1500, 300], look_at: [0, 0, 0]}\n"
                                 "terrain: {grid: [[0, 0], [0, 0]], origin: [-1100, -1100], spacing: [2200, 2200]}\n"
                                 "objects:\n  - {layout: boxes.csv, shape: box, size: [1, 1, 3]}\n");
    CHECK(path != NULL);
    if (!path) return;
    uint64_t before = peak_bytes();
    err_buf err = {{0}};
    scene_file *sf = scene_file_load(path, NULL, &err);
    build_options bo = {.quiet = 1, .threads = 1};
    scene *s = sf ? scene_build(sf, NULL, &bo, &err) : NULL;
    accel a;
    int built = s && !accel_build(&a, s, 1, &err);
    if (!built) fprintf(stderr, "%s\n", err.msg);
    CHECK(built);
    if (built) accel_free(&a);
    scene_free(s);
    scene_file_free(sf);
    if (!built) return;
    uint64_t taken = peak_bytes() - before;
    fprintf(stderr, "%d boxes: the peak grew by %.1f MiB\n", BOXES, taken / 1048576.0);
    CHECK(!loads_within(path, taken / 2)); /* the estimate is at least half of it */
    CHECK(loads_within(path, taken * 3));  /* and at most three times */
}

TEST_LIST(TEST_CASE(boxes_estimate_what_they_take))
