/* test_ztv_trace.c — the visibility map's tracer against cases whose answer is known: a target
 * behind a ridge (the cells that see over it follow from the geometry), a low target beyond the
 * curved Earth's horizon (visible to the distance sqrt(h_o / c) + sqrt(h_t / c)), a wall of
 * trees that hides a target with vegetation screening and not on bare earth, leaves with holes
 * that let some sightlines through, observers under a crown and inside a building, two named
 * developments told apart, the same map from one thread and from four, and from parts that
 * compute every third row each (the ranks of an MPI job). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "io/image_io.h"
#include "scene_fixture.h"
#include "work_dir.h"
#include "ztv/ztv_grid.h"
#include "ztv/ztv_trace.h"

/* Every block's layers, copied into whole-map arrays. */
typedef struct map_copy {
    ztv_grid grid;
    uint16_t *visible[ZTV_MODES];
    uint8_t *cls[ZTV_MODES];
    uint32_t *developments[ZTV_MODES];
    float *ground;
    uint32_t next_row;
    uint32_t part, parts;           /* the part being traced: only its rows are copied */
} map_copy;

static int copy_block(void *user, const ztv_block *b, err_buf *err)
{
    (void)err;
    map_copy *m = user;
    CHECK_INT(b->j0, m->next_row);
    m->next_row = b->j0 + b->rows;
    size_t nx = m->grid.nx;
    for (uint32_t r = 0; r < b->rows; r++) {
        if ((b->j0 + r) % m->parts != m->part) continue;
        size_t at = (size_t)(b->j0 + r) * nx, from = (size_t)r * nx;
        memcpy(m->ground + at, b->ground + from, nx * sizeof(float));
        for (int k = 0; k < ZTV_MODES; k++)
            if (b->layer[k]) {
                memcpy(m->visible[k] + at, b->layer[k]->visible + from, nx * sizeof(uint16_t));
                memcpy(m->cls[k] + at, b->layer[k]->cls + from, nx);
                memcpy(m->developments[k] + at, b->layer[k]->developments + from, nx * sizeof(uint32_t));
            }
    }
    return 0;
}

static void map_free(map_copy *m)
{
    for (int k = 0; k < ZTV_MODES; k++) free(m->visible[k]), free(m->cls[k]), free(m->developments[k]);
    free(m->ground);
}

/* Maps scene file `name` (text) with cell size `cell`, screened as `mode`, into *m, as `parts`
 * parts one after another (1: the whole map at once). */
static int run_map_parts(const char *name, const char *text, double cell, ztv_mode mode, unsigned threads, int flat,
                         uint32_t parts, map_copy *m, scene **out)
{
    memset(m, 0, sizeof *m);
    static char full[1 << 17];
    snprintf(full, sizeof full, "camera: {position: [0, -10, 2], look_at: [0, 0, 0]}\n%s", text);
    const char *path = work_file(name, full);
    err_buf err = {{0}};
    scene_file *sf = path ? scene_file_load(path, NULL, &err) : NULL;
    if (!sf) fprintf(stderr, "%s\n", err.msg);
    CHECK(sf != NULL);
    if (!sf) return -1;
    build_options bo = {.quiet = 1};
    scene *s = scene_build(sf, NULL, &bo, &err);
    CHECK(s != NULL);
    ztv_targets t;
    accel a;
    int rc = !s || ztv_targets_build(&t, sf, s, 1, &err) ? -1 : 0;
    if (!rc && accel_build(&a, s, 1, &err)) {
        ztv_targets_free(&t);
        rc = -1;
    }
    if (!rc) {
        ztv_job job = {.scene = s, .accel = &a, .targets = &t, .observer_height = sf->ztv.observer_height,
                       .radius = INFINITY, .screened = mode, .earth = flat ? NULL : &s->earth, .threads = threads,
                       .quiet = 1};
        rc = ztv_grid_make(s, &t, cell, INFINITY, &job.grid, &err);
        m->grid = job.grid;
        size_t n = (size_t)job.grid.nx * job.grid.ny;
        m->ground = calloc(n, sizeof(float));
        for (int k = 0; k < ZTV_MODES; k++)
            m->visible[k] = calloc(n, 2), m->cls[k] = calloc(n, 1), m->developments[k] = calloc(n, 4);
        for (m->parts = parts, m->part = 0; !rc && m->part < parts; m->part++) {
            job.part = m->part, job.parts = parts, m->next_row = 0;
            rc = ztv_trace(&job, copy_block, m, NULL, &err);
            CHECK_INT(m->next_row, job.grid.ny);
        }
        accel_free(&a);
        ztv_targets_free(&t);
    }
    if (rc) fprintf(stderr, "%s\n", err.msg);
    CHECK_INT(rc, 0);
    scene_file_free(sf);
    if (out) *out = s;
    else scene_free(s);
    return rc;
}

static int run_map(const char *name, const char *text, double cell, ztv_mode mode, unsigned threads, int flat,
                   map_copy *m, scene **out)
{
    return run_map_parts(name, text, cell, mode, threads, flat, 1, m, out);
}

/* A ridge 50 m high along y at x = 0 (a tent 100 m to each side), a target 100 m above the
 * ground at x = 500. An observer 2 m up at x < 0 sees it when the straight sightline passes
 * over the crest: 2 + 98 (-x) / (500 - x) >= 50. */
TEST(ridge_hides_what_the_geometry_says)
{
    char text[4096];
    int at = snprintf(text, sizeof text,
                      "terrain: {origin: [-2000, -100], spacing: [100, 100], grid: [");
    for (int row = 0; row < 3; row++) {
        at += snprintf(text + at, sizeof text - at, "%s[", row ? ", " : "");
        for (int i = 0; i <= 40; i++) at += snprintf(text + at, sizeof text - at, "%s%d", i ? ", " : "", i == 20 ? 50 : 0);
        at += snprintf(text + at, sizeof text - at, "]");
    }
    snprintf(text + at, sizeof text - at,
             "]}\nztv: {targets: [{position: [500, 0], height_above_ground: 100}]}\n");
    map_copy m;
    if (run_map("ridge.yaml", text, 0, ZTV_BARE, 2, 1, &m, NULL)) return;
    CHECK_INT(m.grid.nx, 41);
    CHECK_INT(m.grid.ny, 3);
    int checked = 0;
    for (uint32_t i = 0; i < m.grid.nx; i++) {
        double x = m.grid.x0 + i * m.grid.cell;
        int expect = x >= 0 || 2 + 98 * (-x) / (500 - x) >= 50;
        if (x < 0 && fabs(2 + 98 * (-x) / (500 - x) - 50) < 0.5) continue; /* grazing the crest */
        for (uint32_t j = 0; j < m.grid.ny; j++) {
            int got = m.visible[ZTV_BARE][j * m.grid.nx + i];
            if (got != expect) fprintf(stderr, "x %.0f: visible %d, expected %d\n", x, got, expect);
            CHECK_INT(got, expect);
            checked++;
        }
    }
    CHECK(checked >= 120);
    map_free(&m);
}

/* Flat ground 40 km long, a target 10 m up at x = 0, eyes 2 m up, k = 0.13: the target sinks
 * below the horizon beyond sqrt(2 / c) + sqrt(10 / c) = 17,514 m, c = (1 - k) / 2R. */
TEST(curvature_hides_a_low_target_beyond_the_horizon)
{
    const char *text = "terrain: {origin: [-100, -500], spacing: [2500, 1000], grid: [[0, 0, 0, 0, 0, 0, 0, 0, 0, "
                       "0, 0, 0, 0, 0, 0, 0, 0], [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]]}\n"
                       "earth: {curvature: true, refraction: 0.13}\n"
                       "ztv: {targets: [{position: [-100, 0], height_above_ground: 10}]}\n";
    double c = (1 - 0.13) / (2 * 6371000.0), horizon = sqrt(2 / c) + sqrt(10 / c);
    CHECK(fabs(horizon - 17514) < 1);
    map_copy m, flat;
    if (run_map("curved.yaml", text, 100, ZTV_BARE, 2, 0, &m, NULL)) return;
    if (run_map("curved.yaml", text, 100, ZTV_BARE, 2, 1, &flat, NULL)) return;
    uint32_t j = m.grid.ny / 2, near = 0, far = 0;
    for (uint32_t i = 0; i < m.grid.nx; i++) {
        double d = i * m.grid.cell;
        int got = m.visible[ZTV_BARE][j * m.grid.nx + i];
        if (d < horizon - 60) {
            CHECK_INT(got, 1);
            near++;
        }
        if (d > horizon + 60) {
            CHECK_INT(got, 0);
            far++;
        }
        CHECK_INT(flat.visible[ZTV_BARE][j * m.grid.nx + i], 1); /* a flat Earth hides nothing */
    }
    CHECK(near > 150 && far > 200);
    map_free(&m);
    map_free(&flat);
}

/* A hedge of 1 m boxes, 30 m tall (half of it below the ground), across the view at x = 100 hides a target 10 m up at x = 0
 * from the observers behind it with vegetation screening, and not on bare earth; a building
 * over some cells puts their observers inside it. */
static void wall_scene(char *text, size_t size, const char *material_extra)
{
    int at = snprintf(text, size,
                      "terrain: {origin: [-50, -60], spacing: [10, 10], grid: [");
    for (int row = 0; row < 13; row++) {
        at += snprintf(text + at, size - at, "%s[", row ? ", " : "");
        for (int i = 0; i < 41; i++) at += snprintf(text + at, size - at, "%s0", i ? ", " : "");
        at += snprintf(text + at, size - at, "]");
    }
    at += snprintf(text + at, size - at,
                   "]}\nmaterials: {hedge: {albedo: [0.1, 0.3, 0.1]%s}}\n"
                   "species: {box: {shape: box, size: [1, 1, 30], material: hedge}}\n"
                   "objects:\n  - {name: barn, shape: box, size: [30, 30, 8], position: [300, 0, 4]}\n"
                   "plants:\n", material_extra);
    for (int y = -60; y <= 60; y++)
        at += snprintf(text + at, size - at, "  - {species: box, position: [100, %d]}\n", y);
    snprintf(text + at, size - at, "ztv: {targets: [{position: [0, 0], height_above_ground: 10}]}\n");
}

TEST(a_wall_of_trees_screens_and_bare_earth_does_not)
{
    static char text[1 << 16];
    wall_scene(text, sizeof text, "");
    map_copy veg, all;
    if (run_map("wall.yaml", text, 0, ZTV_VEGETATION, 2, 1, &veg, NULL)) return;
    if (run_map("wall.yaml", text, 0, ZTV_ALL, 2, 1, &all, NULL)) return;
    uint32_t behind = 0, inside = 0, under = 0;
    for (uint32_t j = 0; j < veg.grid.ny; j++)
        for (uint32_t i = 0; i < veg.grid.nx; i++) {
            size_t k = (size_t)j * veg.grid.nx + i;
            double x = veg.grid.x0 + i * veg.grid.cell, y = veg.grid.y0 - j * veg.grid.cell;
            CHECK_INT(veg.visible[ZTV_BARE][k], 1); /* flat bare earth: everything in sight */
            if (x > 120 && fabs(y) < 20 && x < 280) { /* behind the middle of the hedge */
                CHECK_INT(veg.visible[ZTV_VEGETATION][k], 0);
                CHECK_INT(veg.cls[ZTV_VEGETATION][k], ZTV_OPEN);
                behind++;
            }
            if (x < 90) CHECK_INT(veg.visible[ZTV_VEGETATION][k], 1); /* in front of it */
            if (fabs(x - 300) < 14 && fabs(y) < 14) { /* inside the barn */
                CHECK_INT(all.cls[ZTV_ALL][k], ZTV_IN_OBJECT);
                CHECK_INT(all.visible[ZTV_ALL][k], 0);
                CHECK_INT(veg.cls[ZTV_VEGETATION][k], ZTV_OPEN); /* the barn does not screen there */
                inside++;
            }
            if (x == 100) under += veg.cls[ZTV_VEGETATION][k] == ZTV_UNDER_CROWN;
        }
    CHECK(behind >= 15 && inside >= 4);
    CHECK(under >= 11); /* the cells on the hedge's line stand inside it */
    map_free(&veg);
    map_free(&all);
}

/* The same hedge with a leaf texture whose alpha is a fine checkerboard of holes: some
 * sightlines pass between the leaves, some do not. */
TEST(holes_in_a_leaf_texture_let_some_sightlines_through)
{
    uint8_t rgba[16 * 16 * 4];
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) {
            uint8_t *p = &rgba[(y * 16 + x) * 4];
            p[0] = 40, p[1] = 120, p[2] = 40, p[3] = (x + y) % 2 ? 255 : 0;
        }
    err_buf err = {{0}};
    CHECK_INT(image_write_u8(work_path("holes.png"), 16, 16, 4, rgba, &err), 0);
    static char text[1 << 16];
    wall_scene(text, sizeof text, ", texture: holes.png, alpha_mask: true");
    map_copy veg;
    if (run_map("holes.yaml", text, 2, ZTV_VEGETATION, 2, 1, &veg, NULL)) return;
    uint32_t seen = 0, hidden = 0;
    for (uint32_t j = 0; j < veg.grid.ny; j++)
        for (uint32_t i = 0; i < veg.grid.nx; i++) {
            double x = veg.grid.x0 + i * veg.grid.cell, y = veg.grid.y0 - j * veg.grid.cell;
            if (x > 120 && x < 280 && fabs(y) < 40) {
                if (veg.visible[ZTV_VEGETATION][(size_t)j * veg.grid.nx + i]) seen++;
                else hidden++;
            }
        }
    fprintf(stderr, "behind the holed hedge: %u cells see the target, %u do not\n", seen, hidden);
    CHECK(seen > 0 && hidden > 0);
    map_free(&veg);
}

/* Two developments named on their objects, each with targets above its footprint: a cell
 * sees bit d of its mask when it sees some target of development d. Behind a wall across the
 * west, the low mast (development "north") is hidden and the tall one ("south") is not. */
TEST(two_developments_are_told_apart)
{
    const char *text =
        "terrain: {origin: [-200, -200], spacing: [20, 20], grid: [[0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, "
        "0, 0, 0, 0], [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]]}\n"
        "objects:\n"
        "  - {name: wall, shape: box, size: [2, 400, 20], position: [0, 0, 10]}\n"
        "  - {name: low mast, shape: box, size: [1, 1, 10], position: [100, -190], development_name: north}\n"
        "  - {name: tall mast, shape: box, size: [1, 1, 200], position: [100, -190], development_name: south}\n"
        "ztv: {samples: 8}\n";
    map_copy m;
    if (run_map("two.yaml", text, 10, ZTV_ALL, 2, 1, &m, NULL)) return;
    uint32_t west = 0, east = 0;
    for (uint32_t i = 0; i < m.grid.nx; i++) {
        double x = m.grid.x0 + i * m.grid.cell;
        size_t k = (size_t)(m.grid.ny - 1) * m.grid.nx + i; /* the southern row */
        CHECK_INT(m.developments[ZTV_BARE][k], 3u);     /* both in sight on bare earth */
        if (x < -50) { /* only the tall one */
            CHECK_INT(m.developments[ZTV_ALL][k], 2u);
            west++;
        }
        if (x > 20) {
            CHECK_INT(m.developments[ZTV_ALL][k], 3u);
            east++;
        }
    }
    CHECK(west >= 10 && east >= 10);
    map_free(&m);
}

/* The map does not depend on the thread count. */
TEST(one_thread_and_four_give_the_same_map)
{
    static char text[1 << 16];
    wall_scene(text, sizeof text, "");
    map_copy a, b;
    if (run_map("wall1.yaml", text, 3, ZTV_ALL, 1, 0, &a, NULL)) return;
    if (run_map("wall4.yaml", text, 3, ZTV_ALL, 4, 0, &b, NULL)) return;
    size_t n = (size_t)a.grid.nx * a.grid.ny;
    CHECK(memcmp(a.visible[ZTV_ALL], b.visible[ZTV_ALL], n * 2) == 0);
    CHECK(memcmp(a.visible[ZTV_BARE], b.visible[ZTV_BARE], n * 2) == 0);
    CHECK(memcmp(a.cls[ZTV_ALL], b.cls[ZTV_ALL], n) == 0);
    map_free(&a);
    map_free(&b);
}

/* Three parts, each computing every third row, give the map of one (ground, counts, classes and
 * developments, in both modes). */
TEST(three_parts_give_the_map_of_one)
{
    static char text[1 << 16];
    wall_scene(text, sizeof text, "");
    map_copy a, b;
    if (run_map("parts1.yaml", text, 3, ZTV_ALL, 2, 0, &a, NULL)) return;
    if (run_map_parts("parts3.yaml", text, 3, ZTV_ALL, 1, 0, 3, &b, NULL)) return;
    size_t n = (size_t)a.grid.nx * a.grid.ny;
    CHECK(a.grid.ny > 3);
    CHECK(memcmp(a.ground, b.ground, n * sizeof(float)) == 0);
    for (int k = ZTV_BARE; k <= ZTV_ALL; k += ZTV_ALL) {
        CHECK(memcmp(a.visible[k], b.visible[k], n * 2) == 0);
        CHECK(memcmp(a.cls[k], b.cls[k], n) == 0);
        CHECK(memcmp(a.developments[k], b.developments[k], n * 4) == 0);
    }
    map_free(&a);
    map_free(&b);
}

TEST_LIST(TEST_CASE(ridge_hides_what_the_geometry_says), TEST_CASE(curvature_hides_a_low_target_beyond_the_horizon),
          TEST_CASE(a_wall_of_trees_screens_and_bare_earth_does_not),
          TEST_CASE(holes_in_a_leaf_texture_let_some_sightlines_through),
          TEST_CASE(two_developments_are_told_apart), TEST_CASE(one_thread_and_four_give_the_same_map),
          TEST_CASE(three_parts_give_the_map_of_one))
