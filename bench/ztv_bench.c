/* ztv_bench.c — the visibility map's speed against raw Embree on the same rays and against
 * gdal_viewshed on the same map, measured in one run on one machine.
 *
 * The scene, built in code: a 1,000 x 1,000-node terrain of hills (10 m apart, 150 m of relief),
 * one development of ten turbine hubs 150 m above the ground in two rows of five near its centre,
 * and a forest of 150,000 trees (a crown of 320 triangles on a stem, 8 to 25 m tall) in stands
 * over a sixth of the ground. The map's grid is the terrain's nodes: 1,000,000 cells, observer
 * 2 m above each, 10,000,000 cell-targets.
 *
 *  1. sylva's tracer (ztv/ztv_trace.h) makes the bare-earth map alone, then the bare-earth and
 *     the vegetation maps together (screening vegetation), on the threads asked (default 2):
 *     wall time, from the built Embree scene to the last block handed over, and cell-targets per
 *     second;
 *  2. raw Embree: the same rays, cast with rtcOccluded1 in a plain loop over rows on as many
 *     threads (rows interleaved), through the same Embree scene with the same masks and the same
 *     ends (a gap at each), choosing the same way which sightline of a pair to cast first (the
 *     one that has settled more of the thread's pairs so far; only bare earth for a cell under a
 *     crown): rays per second, and the tracer's share of it. Each time is the best of 3 runs, the
 *     tracer's and the loop's taken in turn (the machine may be busy). The loop's visible counts
 *     must equal the maps' (else it did not answer the same questions); its ray count differs
 *     from the tracer's by the few pairs whose order the threads' other rows decided otherwise.
 *     For scale, the bare-earth rays also through an Embree scene of the terrain alone;
 *  3. gdal_viewshed over the same terrain written as a GeoTIFF: one run per target (-cc 0), as a
 *     ZTV is made with it, timed as commands (the best of 3 rounds of 10).
 * The Earth is flat (curvature off), so that a cell-target is one straight ray for the tracer
 * and the loop alike; --curvature also times the tracer with the Earth's curvature and
 * refraction (its sightlines are then chains of chords, so it has no raw baseline).
 *
 * usage: ztv_bench [--cells N] [--trees N] [--threads N] [--curvature] [--no-gdal]
 */
#include <embree3/rtcore.h>
#include <gdal.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "bench_machine.h"
#include "render/accel.h"
#include "scene/scene.h"
#include "scene_build/scene_build.h"
#include "scene_build/shapes.h"
#include "util/progress.h"
#include "util/rng.h"
#include "ztv/ztv_grid.h"
#include "ztv/ztv_sight.h"
#include "ztv/ztv_trace.h"

#define SPACING 10.0       /* metres between nodes */
#define N_TARGETS 10u
#define HUB 150.0          /* target height above the ground */
#define EYE 2.0            /* observer height above the ground */
#define REPEATS 3          /* a time is the best of this many runs; the tracer's and the loop's in turn */

static double hill(double x, double y)
{
    return 60 * sin(x / 900) * cos(y / 1300) + 35 * sin(x / 310 + y / 470) + 12 * sin(x / 97 - y / 130) + 0.004 * x;
}

/* 1 where a forest stand grows. */
static int in_stand(double x, double y)
{
    return sin(x / 410) * cos(y / 350) + 0.6 * sin(x / 150 + y / 190) > 0.75;
}

static sylva_heightfield *terrain_new(uint32_t n)
{
    sylva_heightfield *hf = calloc(1, sizeof *hf);
    float *z = malloc((size_t)n * n * sizeof *z);
    if (!hf || !z) return free(hf), free(z), NULL;
    double half = 0.5 * (n - 1) * SPACING;
    *hf = (sylva_heightfield){.size = sizeof *hf, .nx = n, .ny = n, .x0 = -half, .y0 = -half, .dx = SPACING,
                              .dy = SPACING, .z = z, .water_material = -1};
    for (uint32_t j = 0; j < n; j++)
        for (uint32_t i = 0; i < n; i++) z[(size_t)j * n + i] = (float)hill(i * SPACING - half, j * SPACING - half);
    return hf;
}

/* A tree 10 m tall: a crown (icosphere of radius 3 m centred 7 m up) on a stem. */
static mesh *tree_mesh(int32_t mat, err_buf *err)
{
    mesh *m = mesh_new();
    shape_spec crown = {.kind = SHAPE_SPHERE, .radius = 3, .subdivisions = 2};
    if (!m || shape_build(&crown, mat, m, err)) return mesh_free(m), NULL;
    for (uint32_t v = 0; v < m->nv; v++) m->pos[3 * v + 2] += 7.0f;
    float stem[] = {-0.2f, -0.2f, 0, 0.2f, -0.2f, 0, 0.2f, 0.2f, 0, -0.2f, 0.2f, 0,
                    -0.2f, -0.2f, 4.5f, 0.2f, -0.2f, 4.5f, 0.2f, 0.2f, 4.5f, -0.2f, 0.2f, 4.5f};
    uint32_t sides[] = {0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
    if (mesh_append(m, stem, NULL, NULL, 8, sides, NULL, mat, 8, err)) return mesh_free(m), NULL;
    return m;
}

/* The scene with its forest, and the development's targets (local, on nodes). */
static scene *build(uint32_t cells, uint32_t trees, double target[N_TARGETS][3], err_buf *err)
{
    scene *s = scene_new();
    if (!s || !(s->terrain = terrain_new(cells)) || !(s->species = calloc(1, sizeof(species))))
        return scene_free(s), err_nomem(err, "out of memory for the scene"), NULL;
    for (uint32_t t = 0; t < N_TARGETS; t++) { /* two rows of five, 500 m apart */
        double x = -1000.0 + 500.0 * (t % 5), y = t < 5 ? 250.0 : -250.0, z;
        scene_terrain_height(s, x, y, &z);
        target[t][0] = x, target[t][1] = y, target[t][2] = z + HUB;
    }
    s->species[0] = (species){.name = strdup("tree"), .first_prototype = 0, .n_variants = 1};
    s->n_species = 1;
    mesh *m = tree_mesh(s->default_material, err);
    sylva_plant *plants = malloc((size_t)trees * sizeof *plants);
    if (!m || !plants || scene_add_prototype(s, 0, 0, 1.0, 10.0, m, err) < 0) {
        if (!plants) err_nomem(err, "out of memory for %u plants", trees);
        return free(plants), scene_free(s), NULL;
    }
    sylva_rng r;
    rng_stream(&r, 14, "ztv bench forest", 0);
    double half = 0.5 * (cells - 1) * SPACING;
    for (uint32_t k = 0; k < trees;) {
        double x = -half + 2 * half * rng_next_double(&r), y = -half + 2 * half * rng_next_double(&r);
        double rot = 2 * M_PI * rng_next_double(&r), h = 8 + 17 * rng_next_double(&r);
        if (in_stand(x, y))
            plants[k++] = (sylva_plant){.size = sizeof(sylva_plant), .position = {x, y, 0}, .snap_to_terrain = 1,
                                        .rotation = rot, .height = h, .age = 1};
    }
    int rc = scene_place_plants(s, plants, trees, err);
    free(plants);
    return rc ? scene_free(s), NULL : s;
}

/* --- sylva's tracer ------------------------------------------------------------------------ */

/* What the sink keeps of the maps: each mode's visible cell-targets, and the class of every cell
 * in the screened mode (the raw loop casts only bare-earth rays from a cell under a crown). */
typedef struct map_record {
    ztv_mode screened;
    uint32_t nx;
    uint8_t *cls;          /* nx * ny; owned by the caller */
    uint64_t visible[ZTV_MODES];
} map_record;

static int record_block(void *user, const ztv_block *b, err_buf *err)
{
    (void)err;
    map_record *r = user;
    size_t n = (size_t)b->rows * r->nx, first = (size_t)b->j0 * r->nx;
    for (int m = 0; m < ZTV_MODES; m++)
        for (size_t k = 0; b->layer[m] && k < n; k++) r->visible[m] += b->layer[m]->visible[k];
    const ztv_layer *l = b->layer[r->screened];
    memcpy(r->cls + first, l->cls, n);
    return 0;
}

/* One map of job's mode; its wall time, or -1 with err. */
static double run_tracer(const ztv_job *job, map_record *rec, ztv_stats *st, err_buf *err)
{
    rec->screened = job->screened;
    memset(rec->visible, 0, sizeof rec->visible);
    double t0 = progress_now();
    if (ztv_trace(job, record_block, rec, st, err)) return -1;
    return progress_now() - t0;
}

/* --- raw Embree: the same rays through rtcOccluded1 ---------------------------------------- */

typedef struct raw_job {
    const accel *acc;
    const ztv_grid *grid;
    const sylva_heightfield *hf;
    const double (*target)[3];
    const uint8_t *cls;    /* the screened mode's classes, or NULL for bare earth alone */
    unsigned screen_mask;
    uint32_t first, stride; /* rows first, first + stride, ... (interleaved: the threads' loads even out) */
    uint64_t rays, visible[2];
} raw_job;

/* The straight sightline from eye to target as ztv_sight_clear casts it: 1 when clear. */
static int raw_clear(RTCScene top, const float eye[3], const double t[3], unsigned mask)
{
    double d[3] = {t[0] - eye[0], t[1] - eye[1], t[2] - eye[2]};
    double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), far = len - ZTV_SIGHT_GAP;
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    struct RTCRay ray = {.org_x = eye[0], .org_y = eye[1], .org_z = eye[2],
                         .tnear = (float)fmin(ZTV_SIGHT_GAP, 0.5 * far), .dir_x = (float)(d[0] / len),
                         .dir_y = (float)(d[1] / len), .dir_z = (float)(d[2] / len),
                         .tfar = (float)far, .mask = mask};
    rtcOccluded1(top, &ctx, &ray);
    return ray.tfar >= 0;
}

static void *raw_rows(void *arg)
{
    raw_job *j = arg;
    const ztv_grid *g = j->grid;
    uint64_t rays = 0, visible[2] = {0, 0}; /* local: the jobs share cache lines */
    uint64_t bare_clear = 0, screened_blocked = 0; /* choose which sightline to cast first */
    for (uint32_t row = j->first; row < g->ny; row += j->stride)
        for (uint32_t i = 0; i < g->nx; i++) {
            double x, y, ground;
            ztv_cell_centre(g, i, row, &x, &y);
            ztv_ground(j->acc->scene, x, y, &ground);
            float eye[3] = {(float)x, (float)y, (float)(ground + EYE)};
            int open = j->cls && j->cls[(size_t)row * g->nx + i] == ZTV_OPEN;
            for (uint32_t t = 0; t < N_TARGETS; t++) {
                int bare, screened = 0;
                if (!open) {
                    bare = (rays++, raw_clear(j->acc->top, eye, j->target[t], ACCEL_MASK_GROUND));
                } else if (bare_clear < screened_blocked) { /* bare earth first: it settles more */
                    bare = (rays++, raw_clear(j->acc->top, eye, j->target[t], ACCEL_MASK_GROUND));
                    screened = bare && (rays++, raw_clear(j->acc->top, eye, j->target[t], j->screen_mask));
                } else { /* the screened sightline first */
                    screened = (rays++, raw_clear(j->acc->top, eye, j->target[t], j->screen_mask));
                    bare = screened || (rays++, raw_clear(j->acc->top, eye, j->target[t], ACCEL_MASK_GROUND));
                }
                if (open) bare_clear += bare, screened_blocked += !screened;
                visible[0] += bare, visible[1] += screened;
            }
        }
    j->rays = rays, j->visible[0] = visible[0], j->visible[1] = visible[1];
    return NULL;
}

/* One run of the loop on `threads` threads: its wall time, its tallies in *out. */
static double raw_once(raw_job proto, unsigned threads, raw_job *out)
{
    raw_job jobs[64];
    pthread_t tid[64];
    double t0 = progress_now();
    for (unsigned k = 0; k < threads; k++) {
        jobs[k] = proto;
        jobs[k].first = k, jobs[k].stride = threads;
        pthread_create(&tid[k], NULL, raw_rows, &jobs[k]);
    }
    *out = proto;
    for (unsigned k = 0; k < threads; k++) {
        pthread_join(tid[k], NULL);
        out->rays += jobs[k].rays, out->visible[0] += jobs[k].visible[0], out->visible[1] += jobs[k].visible[1];
    }
    return progress_now() - t0;
}

/* The tracer's map of job's mode and the loop over the same rays (and over `also`, when not
 * NULL), in turn REPEATS times: their best wall times in *t_sylva, *t_raw (and *t_also), the
 * tallies in *st and *got. 0, or -1 with err. */
static int time_mode(const ztv_job *job, map_record *rec, raw_job raw, const raw_job *also, unsigned threads,
                     double *t_sylva, double *t_raw, double *t_also, ztv_stats *st, raw_job *got, err_buf *err)
{
    *t_sylva = *t_raw = INFINITY;
    if (also) *t_also = INFINITY;
    for (int rep = 0; rep < REPEATS; rep++) {
        double t = run_tracer(job, rec, st, err);
        if (t < 0) return -1;
        *t_sylva = fmin(*t_sylva, t);
        *t_raw = fmin(*t_raw, raw_once(raw, threads, got));
        raw_job unused;
        if (also) *t_also = fmin(*t_also, raw_once(*also, threads, &unused));
    }
    return 0;
}

/* --- gdal_viewshed ------------------------------------------------------------------------- */

/* The terrain as a Float32 GeoTIFF at path (pixels = nodes, local metres) on a transverse
 * Mercator of a sphere; 0 or -1. */
static int write_terrain(const char *path, const sylva_heightfield *hf)
{
    GDALAllRegister();
    GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path, (int)hf->nx, (int)hf->ny, 1, GDT_Float32, NULL);
    if (!ds) return -1;
    double gt[6] = {hf->x0 - 0.5 * hf->dx, hf->dx, 0, hf->y0 + (hf->ny - 0.5) * hf->dy, 0, -hf->dy};
    int rc = GDALSetGeoTransform(ds, gt) != CE_None ||
             GDALSetProjection(ds, "PROJCS[\"tmerc\",GEOGCS[\"sphere\",DATUM[\"sphere\","
                                   "SPHEROID[\"sphere\",6371000,0]],PRIMEM[\"Greenwich\",0],"
                                   "UNIT[\"degree\",0.0174532925199433]],PROJECTION[\"Transverse_Mercator\"],UNIT[\"metre\",1]]") != CE_None;
    for (uint32_t row = 0; row < hf->ny && !rc; row++)
        rc = GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, (int)row, (int)hf->nx, 1,
                          hf->z + (size_t)(hf->ny - 1 - row) * hf->nx, (int)hf->nx, 1, GDT_Float32, 0, 0) != CE_None;
    GDALClose(ds);
    return rc ? -1 : 0;
}

/* Seconds for gdal_viewshed from every target over dem, one command each; -1 when one fails. */
static double gdal_viewshed_time(const char *dem, const char *dir, const double (*target)[3])
{
    double t0 = progress_now();
    for (uint32_t t = 0; t < N_TARGETS; t++) {
        char cmd[1024];
        snprintf(cmd, sizeof cmd, "gdal_viewshed -q -ox %.3f -oy %.3f -oz %g -tz %g -cc 0 %s %s/viewshed_%u.tif",
                 target[t][0], target[t][1], HUB, EYE, dem, dir, t);
        if (system(cmd) != 0) return -1;
    }
    return progress_now() - t0;
}

/* The 1, 5 and 15 minute load averages (/proc/loadavg): other work on the machine shows in them. */
static const char *load_average(void)
{
    static char line[64];
    FILE *f = fopen("/proc/loadavg", "r");
    snprintf(line, sizeof line, "unknown");
    if (f && fgets(line, sizeof line, f)) line[strcspn(line, "\n")] = '\0';
    if (f) fclose(f);
    for (int spaces = 0, k = 0; line[k]; k++) /* keep the three averages */
        if (line[k] == ' ' && ++spaces == 3) line[k] = '\0';
    return line;
}

/* sylva / raw is the ratio of their rays per second (their ray counts may differ a little). */
static void print_map(const char *what, double seconds, const ztv_stats *st, double raw, uint64_t raw_rays)
{
    printf("sylva ztv, %-22s %6.3f s: %6.2f M cell-targets/s, %.2f M rays/s (%llu rays)  goal <= 10 s\n", what,
           seconds, st->pairs / seconds / 1e6, st->rays / seconds / 1e6, (unsigned long long)st->rays);
    if (raw > 0)
        printf("raw Embree, the same rays:     %6.3f s: %6.2f M rays/s (%llu rays); sylva / raw: %.2f "
               "(goal >= 0.7)\n", raw, raw_rays / raw / 1e6, (unsigned long long)raw_rays,
               (st->rays / seconds) / (raw_rays / raw));
}

int main(int argc, char **argv)
{
    uint32_t cells = 1000, trees = 150000;
    unsigned threads = 2;
    int curvature = 0, gdal = 1;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--curvature")) curvature = 1;
        else if (!strcmp(argv[i], "--no-gdal")) gdal = 0;
        else if (i + 1 < argc && !strcmp(argv[i], "--cells")) cells = (uint32_t)atol(argv[++i]);
        else if (i + 1 < argc && !strcmp(argv[i], "--trees")) trees = (uint32_t)atol(argv[++i]);
        else if (i + 1 < argc && !strcmp(argv[i], "--threads")) threads = (unsigned)atol(argv[++i]);
        else {
            fprintf(stderr, "usage: ztv_bench [--cells N] [--trees N] [--threads N] [--curvature] [--no-gdal]\n");
            return 1;
        }
    }
    if (cells < 300 || cells > 20000 || threads < 1 || threads > 64)
        return fprintf(stderr, "ztv_bench: --cells 300..20000, --threads 1..64\n"), 1;
    char cpu[256];
    bench_cpu_model(cpu, sizeof cpu);
    printf("machine: %s, %ld processors online; %u threads; load average %s\n", cpu,
           sysconf(_SC_NPROCESSORS_ONLN), threads, load_average());
    err_buf err = {{0}};
    double target[N_TARGETS][3];
    double t0 = progress_now();
    scene *s = build(cells, trees, target, &err);
    accel acc;
    if (!s || accel_build(&acc, s, threads, &err)) return fprintf(stderr, "ztv_bench: %s\n", err.msg), 4;
    printf("scene: %u x %u nodes %g m apart, %u targets %g m above the ground, %u trees; built with its Embree "
           "scene in %.2f s\n", cells, cells, SPACING, N_TARGETS, HUB, s->n_instances, progress_now() - t0);

    /* the development: one, of the ten targets */
    double xy[N_TARGETS][2], centre[1][2] = {{0, 0}};
    uint32_t dev[N_TARGETS] = {0};
    const char *names[1] = {"wind farm"};
    for (uint32_t t = 0; t < N_TARGETS; t++) xy[t][0] = target[t][0], xy[t][1] = target[t][1];
    for (uint32_t t = 0; t < N_TARGETS; t++) centre[0][0] += xy[t][0] / N_TARGETS, centre[0][1] += xy[t][1] / N_TARGETS;
    ztv_targets tg = {.source = ZTV_TARGETS_GIVEN, .n = N_TARGETS, .p = target, .xy = xy, .development = dev,
                      .n_developments = 1, .names = names, .centre = centre};
    ztv_job job = {.scene = s, .accel = &acc, .targets = &tg, .observer_height = EYE, .radius = INFINITY,
                   .screened = ZTV_BARE, .threads = threads, .quiet = 1};
    if (ztv_grid_make(s, &tg, 0, INFINITY, &job.grid, &err)) return fprintf(stderr, "ztv_bench: %s\n", err.msg), 4;
    const double pairs = (double)job.grid.nx * job.grid.ny * N_TARGETS;
    printf("map: %u x %u cells of %g m, observer %g m: %.0f cell-targets; flat Earth\n", job.grid.nx, job.grid.ny,
           job.grid.cell, EYE, pairs);
    map_record rec = {.nx = job.grid.nx, .cls = malloc((size_t)job.grid.nx * job.grid.ny)};
    if (!rec.cls) return fprintf(stderr, "ztv_bench: out of memory\n"), 4;

    /* bare earth alone; and, for what skipping the plants by mask costs, the same rays through an
     * Embree scene of the terrain alone */
    ztv_stats st;
    raw_job raw = {.acc = &acc, .grid = &job.grid, .hf = s->terrain, .target = (const double(*)[3])target}, got;
    scene *ground = scene_new();
    accel acc_ground;
    if (!ground || !(ground->terrain = terrain_new(cells)) || accel_build(&acc_ground, ground, threads, &err))
        return fprintf(stderr, "ztv_bench: %s\n", err.msg[0] ? err.msg : "out of memory"), 4;
    raw_job alone = raw;
    alone.acc = &acc_ground;
    double t_bare, r_bare, r_alone;
    if (time_mode(&job, &rec, raw, &alone, threads, &t_bare, &r_bare, &r_alone, &st, &got, &err))
        return fprintf(stderr, "ztv_bench: %s\n", err.msg), 4;
    accel_free(&acc_ground);
    scene_free(ground);
    print_map("bare earth:", t_bare, &st, r_bare, got.rays);
    printf("raw Embree, the same rays through the terrain alone (no plants to skip): %6.3f s: %6.2f M rays/s\n",
           r_alone, got.rays / r_alone / 1e6);
    if (got.visible[0] != rec.visible[ZTV_BARE])
        printf("MISMATCH: the raw loop sees %llu cell-targets in %llu rays, the map %llu in %llu\n",
               (unsigned long long)got.visible[0], (unsigned long long)got.rays,
               (unsigned long long)rec.visible[ZTV_BARE], (unsigned long long)st.rays);
    uint64_t bare_visible = rec.visible[ZTV_BARE];

    /* bare earth and vegetation */
    job.screened = ZTV_VEGETATION;
    raw.cls = rec.cls, raw.screen_mask = ztv_mode_mask(ZTV_VEGETATION);
    double t_veg, r_veg;
    if (time_mode(&job, &rec, raw, NULL, threads, &t_veg, &r_veg, NULL, &st, &got, &err))
        return fprintf(stderr, "ztv_bench: %s\n", err.msg), 4;
    print_map("bare and vegetation:", t_veg, &st, r_veg, got.rays);
    if (got.visible[0] != rec.visible[ZTV_BARE] || got.visible[1] != rec.visible[ZTV_VEGETATION])
        printf("MISMATCH: the raw loop sees %llu / %llu cell-targets in %llu rays, the map %llu / %llu in %llu\n",
               (unsigned long long)got.visible[0], (unsigned long long)got.visible[1], (unsigned long long)got.rays,
               (unsigned long long)rec.visible[ZTV_BARE], (unsigned long long)rec.visible[ZTV_VEGETATION],
               (unsigned long long)st.rays);
    size_t under = 0;
    for (size_t k = 0; k < (size_t)job.grid.nx * job.grid.ny; k++) under += rec.cls[k] == ZTV_UNDER_CROWN;
    printf("  visible cell-targets: bare %llu (%.1f %%), vegetation %llu (%.1f %%); %zu cells under a crown\n",
           (unsigned long long)bare_visible, 100.0 * bare_visible / pairs,
           (unsigned long long)rec.visible[ZTV_VEGETATION], 100.0 * rec.visible[ZTV_VEGETATION] / pairs, under);

    if (curvature) {
        earth_settings earth = {.curvature = 1, .refraction = 0.13, .radius = 6371000};
        job.earth = &earth;
        const ztv_mode modes[2] = {ZTV_BARE, ZTV_VEGETATION};
        const char *what[2] = {"bare, curved Earth:", "vegetation, curved:"};
        for (int m = 0; m < 2; m++) {
            job.screened = modes[m];
            double best = INFINITY;
            for (int rep = 0; rep < REPEATS; rep++) {
                double t = run_tracer(&job, &rec, &st, &err);
                if (t < 0) return fprintf(stderr, "ztv_bench: %s\n", err.msg), 4;
                best = fmin(best, t);
            }
            print_map(what[m], best, &st, 0, 0);
        }
    }

    if (gdal) {
        char dir[] = "/tmp/ztv_bench.XXXXXX", dem[64], cmd[128];
        if (!mkdtemp(dir)) return perror("ztv_bench: mkdtemp"), 3;
        snprintf(dem, sizeof dem, "%s/terrain.tif", dir);
        double g = write_terrain(dem, s->terrain) ? -1 : INFINITY;
        for (int rep = 0; rep < REPEATS && g >= 0; rep++) {
            double t = gdal_viewshed_time(dem, dir, (const double(*)[3])target);
            g = t < 0 ? -1 : fmin(g, t);
        }
        if (g < 0) printf("gdal_viewshed: not run (no gdal_viewshed, or it failed)\n");
        else
            printf("gdal_viewshed, bare earth:     %6.3f s for %u runs, one per target: %.2f M cell-targets/s; "
                   "sylva's bare map takes %.2f times as long\n", g, N_TARGETS, pairs / g / 1e6, t_bare / g);
        snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
        if (system(cmd) != 0) fprintf(stderr, "ztv_bench: could not remove %s\n", dir);
    }
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    printf("peak memory: %.0f MiB; load average at the end %s\n", ru.ru_maxrss / 1024.0, load_average());
    free(rec.cls);
    accel_free(&acc);
    scene_free(s);
    return 0;
}
