/* ztv_bench.c — sylva's visibility map against gdal_viewshed, measured honestly in one run on
 * one machine: CPU time and wall time for both tools at the same thread count, as whole processes
 * the way a user runs them and as the tracing alone, on a real DTM and a generated one.
 *
 * The DTMs: the generated one, 1,000 x 1,000 nodes 10 m apart (hills, 150 m of relief; --cells),
 * and a real one (--dem, default the shared Zion SRTM DTM, 465 x 457 nodes taken as 83 m squares:
 * the largest real DTM of ../shared/data; none there has 10^6 nodes). Each is written as a
 * GeoTIFF on a transverse Mercator of sylva's Earth sphere, which both tools read. The targets:
 * up to 100 hubs HUB m above the ground on a square lattice 300 m apart round the centre; the
 * observers EYE m above every node; the Earth curved with refraction 0.13 (gdal_viewshed -cc 0.87).
 *
 *  1. Whole processes: `sylva ztv SCENE -o DIR -q --threads N` (the scene file names the GeoTIFF
 *     and the targets) against `gdal_viewshed` once per target, N of them at a time; sylva twice:
 *     like for like with `--products raster` (the GeoTIFF alone, as gdal_viewshed writes), and
 *     as run by default (every product: the GeoTIFF, the map page as PNG and PDF, the summary, the
 *     GeoPackage). CPU time is the processes' own (user + system, from wait4), wall time the whole
 *     batch's. For 1, 10 and 100 targets, on 1 thread (one gdal_viewshed process at a time) and
 *     on N (--threads, default 2; N gdal_viewshed processes in parallel); the cost per target and
 *     sylva's CPU time over gdal_viewshed's.
 *  2. The tracing alone: sylva's ztv_trace over the scene built in code (the Embree scene built
 *     beforehand, outside the clock) against GDALViewshedGenerate called in-process into memory,
 *     per target, on 1 and on N threads (N targets at once), CPU and wall time.
 *  3. Screening: on the generated DTM with --trees trees (default 100,000; a crown of 320
 *     triangles on a stem) in stands over a sixth of the ground, the bare-earth and the
 *     vegetation maps together against bare earth alone, 10 targets, tracing alone.
 * Each time is the best of --repeats runs (default 3; the machine may be busy, and the load average
 * is printed).
 * The goals of the visibility map are printed beside the figures they judge.
 *
 * usage: ztv_bench [--cells N] [--trees N] [--threads N] [--dem FILE] [--sylva PATH] [--repeats N] [--no-gdal]
 *                  [--screening-only]  (the screened map against bare earth alone)
 */
#include <embree3/rtcore.h>
#include <gdal.h>
#include <gdal_alg.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "bench_machine.h"
#include "render/accel.h"
#include "scene/scene.h"
#include "scene_build/scene_build.h"
#include "scene_build/shapes.h"
#include "util/progress.h"
#include "util/rng.h"
#include "ztv/ztv_grid.h"
#include "ztv/ztv_trace.h"

#define SPACING 10.0       /* metres between the generated DTM's nodes */
#define MAX_TARGETS 100u
#define HUB 150.0          /* target height above the ground */
#define EYE 2.0            /* observer height above the ground */
#define REFRACTION 0.13
static int repeats = 3;   /* a time is the best of this many runs (--repeats) */
#define REAL_DEM ZTV_BENCH_DEM /* ../shared/data beside the clone */
#define REAL_CELL 83.0     /* the Zion DTM's 3" cells taken as squares, as tests/ztv does */

static const uint32_t target_counts[] = {1, 10, 100};
#define N_COUNTS (sizeof target_counts / sizeof *target_counts)

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




/* The heightfield of the real DTM: its first band, nodes REAL_CELL m apart centred on the origin;
 * NULL when it cannot be read. */
static sylva_heightfield *terrain_read(const char *path)
{
    GDALAllRegister();
    GDALDatasetH ds = GDALOpen(path, GA_ReadOnly);
    if (!ds) return NULL;
    uint32_t nx = (uint32_t)GDALGetRasterXSize(ds), ny = (uint32_t)GDALGetRasterYSize(ds);
    sylva_heightfield *hf = calloc(1, sizeof *hf);
    float *z = malloc((size_t)nx * ny * sizeof *z); /* the heightfield's; freed with it */
    int ok = hf && z;
    for (uint32_t row = 0; ok && row < ny; row++)
        ok = GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Read, 0, (int)row, (int)nx, 1,
                          z + (size_t)(ny - 1 - row) * nx, (int)nx, 1, GDT_Float32, 0, 0) == CE_None;
    GDALClose(ds);
    if (!ok) return free(hf), free(z), NULL;
    *hf = (sylva_heightfield){.size = sizeof *hf, .nx = nx, .ny = ny, .x0 = -0.5 * (nx - 1) * REAL_CELL,
                              .y0 = -0.5 * (ny - 1) * REAL_CELL, .dx = REAL_CELL, .dy = REAL_CELL, .z = z,
                              .water_material = -1};
    return hf;
}

/* A scene on heightfield hf (taken) with `trees` trees in stands; NULL with err. */
static scene *build(sylva_heightfield *hf, uint32_t trees, err_buf *err)
{
    scene *s = scene_new();
    if (!s || !hf || !(s->species = calloc(1, sizeof(species))))
        return scene_free(s), free(hf), err_nomem(err, "out of memory for the scene"), NULL;
    s->terrain = hf;
    if (!trees) return s;
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
    double hx = 0.5 * (hf->nx - 1) * hf->dx, hy = 0.5 * (hf->ny - 1) * hf->dy;
    for (uint32_t k = 0; k < trees;) {
        double x = -hx + 2 * hx * rng_next_double(&r), y = -hy + 2 * hy * rng_next_double(&r);
        double rot = 2 * M_PI * rng_next_double(&r), h = 8 + 17 * rng_next_double(&r);
        if (in_stand(x, y))
            plants[k++] = (sylva_plant){.size = sizeof(sylva_plant), .position = {x, y, 0}, .snap_to_terrain = 1,
                                        .rotation = rot, .height = h, .age = 1};
    }
    int rc = scene_place_plants(s, plants, trees, err);
    free(plants);
    return rc ? scene_free(s), NULL : s;
}

/* The targets: a square lattice 300 m apart round the centre, HUB m above the ground, the first
 * ones nearest the centre. */
static void targets_place(const scene *s, double p[MAX_TARGETS][3], double xy[MAX_TARGETS][2])
{
    for (uint32_t t = 0; t < MAX_TARGETS; t++) {
        int i = (int)(t % 10) - 5, j = (int)(t / 10) - 5;
        double x = 300.0 * i + 150, y = 300.0 * j + 150, z;
        scene_terrain_height(s, x, y, &z);
        p[t][0] = xy[t][0] = x, p[t][1] = xy[t][1] = y, p[t][2] = z + HUB;
    }
    /* nearest the centre first: 1 and 10 targets stand together, as a development's do */
    for (uint32_t a = 0; a < MAX_TARGETS; a++)
        for (uint32_t b = a + 1; b < MAX_TARGETS; b++)
            if (hypot(p[b][0], p[b][1]) < hypot(p[a][0], p[a][1]) - 1e-9) {
                for (int k = 0; k < 3; k++) {
                    double q = p[a][k];
                    p[a][k] = p[b][k], p[b][k] = q;
                }
                xy[a][0] = p[a][0], xy[a][1] = p[a][1], xy[b][0] = p[b][0], xy[b][1] = p[b][1];
            }
}

/* --- clocks and processes ------------------------------------------------------------------ */

typedef struct cost {
    double cpu, wall;   /* seconds */
} cost;

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static void keep_best(cost *best, cost c)
{
    if (c.cpu < best->cpu) best->cpu = c.cpu;
    if (c.wall < best->wall) best->wall = c.wall;
}

/* Runs the n commands (argv lists), at most `parallel` at once, their output to /dev/null: the
 * processes' CPU time and the batch's wall time; cpu < 0 when one failed. */
static cost run_commands(char **const *cmds, uint32_t n, unsigned parallel)
{
    cost c = {0, 0};
    double t0 = progress_now();
    uint32_t next = 0, running = 0;
    int failed = 0;
    while (next < n || running) {
        if (next < n && running < parallel) {
            fflush(NULL); /* what is buffered is the parent's to write */
            pid_t pid = fork();
            if (pid == 0) {
                if (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr)) _exit(126);
                execvp(cmds[next][0], cmds[next]);
                _exit(127);
            }
            if (pid < 0) return (cost){-1, 0};
            next++, running++;
            continue;
        }
        int status;
        struct rusage ru;
        if (wait4(-1, &status, 0, &ru) < 0) return (cost){-1, 0};
        running--;
        failed |= !WIFEXITED(status) || WEXITSTATUS(status);
        c.cpu += ru.ru_utime.tv_sec + 1e-6 * ru.ru_utime.tv_usec + ru.ru_stime.tv_sec + 1e-6 * ru.ru_stime.tv_usec;
    }
    c.wall = progress_now() - t0;
    if (failed) c.cpu = -1;
    return c;
}

/* --- the two tools as processes ------------------------------------------------------------ */

typedef struct site {
    const char *name;
    const scene *s;
    char dem[256], dir[128];
    double (*p)[3];
} site;

/* The scene file of the first n targets over the site's GeoTIFF at path; 0 or -1. */
static int scene_file_write(const site *st, uint32_t n, const char *path)
{
    FILE *f = fopen(path, "w");
    if (!f) return -1;
    fprintf(f, "camera: {position: [0, -5000, 3000], look_at: [0, 0, 0]}\nterrain:\n  plugin: terrain_ifs\n"
               "  dtm: %s\nearth: {curvature: true, refraction: %g}\nztv:\n  observer_height: %g\n"
               "  screening: none\n  targets:\n", st->dem, REFRACTION, EYE);
    for (uint32_t t = 0; t < n; t++)
        fprintf(f, "    - {position: [%.3f, %.3f], height_above_ground: %g, development: D}\n", st->p[t][0],
                st->p[t][1], HUB);
    return fclose(f) ? -1 : 0;
}

/* sylva ztv over the first n targets on `threads` threads, as a process, writing `products`
 * (--products; NULL: the default, every product). */
static cost sylva_process(const site *st, const char *sylva, uint32_t n, unsigned threads, const char *products)
{
    static unsigned run;
    char yaml[256], out[256], th[16];
    snprintf(yaml, sizeof yaml, "%s/scene_%u.yaml", st->dir, n);
    snprintf(th, sizeof th, "%u", threads);
    if (scene_file_write(st, n, yaml)) return (cost){-1, 0};
    cost best = {INFINITY, INFINITY};
    for (int rep = 0; rep < repeats; rep++) {
        snprintf(out, sizeof out, "%s/ztv_%u", st->dir, run++);
        char *argv[] = {(char *)sylva, "ztv", yaml, "-o", out, "-q", "--threads", th, NULL, NULL, NULL};
        char **cmds[1] = {argv};
        if (products) argv[8] = "--products", argv[9] = (char *)products;
        cost c = run_commands(cmds, 1, 1);
        if (c.cpu < 0) return c;
        keep_best(&best, c);
    }
    return best;
}

/* gdal_viewshed once per target of the first n, `parallel` processes at a time. */
static cost gdal_processes(const site *st, uint32_t n, unsigned parallel)
{
    static char text[MAX_TARGETS][4][160]; /* room for st->dir and a file name */
    char *argv[MAX_TARGETS][16], **cmds[MAX_TARGETS];
    size_t room = sizeof text[0][0];
    for (uint32_t t = 0; t < n; t++) {
        snprintf(text[t][0], room, "%.3f", st->p[t][0]), snprintf(text[t][1], room, "%.3f", st->p[t][1]);
        snprintf(text[t][2], room, "%s/gdal_%u.tif", st->dir, t), snprintf(text[t][3], room, "%g", 1 - REFRACTION);
        char *a[] = {"gdal_viewshed", "-q", "-ox", text[t][0], "-oy", text[t][1], "-oz", "150", "-tz", "2",
                     "-cc", text[t][3], (char *)st->dem, text[t][2], NULL};
        memcpy(argv[t], a, sizeof a);
        cmds[t] = argv[t];
    }
    cost best = {INFINITY, INFINITY};
    for (int rep = 0; rep < repeats; rep++) {
        cost c = run_commands(cmds, n, parallel);
        if (c.cpu < 0) return c;
        keep_best(&best, c);
    }
    return best;
}

/* --- the tracing alone ---------------------------------------------------------------------- */

/* The sink of the tracing alone: the blocks are counted, not written. */
static int count_block(void *user, const ztv_block *b, err_buf *err)
{
    (void)err;
    *(uint64_t *)user += b->rows;
    return 0;
}

/* sylva's tracer over job (its Embree scene built), the best of the runs. */
static cost sylva_tracing(const ztv_job *job, ztv_stats *st, err_buf *err)
{
    cost best = {INFINITY, INFINITY};
    for (int rep = 0; rep < repeats; rep++) {
        uint64_t rows = 0;
        double c0 = cpu_now(), t0 = progress_now();
        if (ztv_trace(job, count_block, &rows, st, err)) return (cost){-1, 0};
        keep_best(&best, (cost){cpu_now() - c0, progress_now() - t0});
    }
    return best;
}

typedef struct gdal_share {
    const char *dem;
    const double (*p)[3];
    uint32_t first, step, n;
    int failed;
} gdal_share;

/* GDALViewshedGenerate for targets first, first + step, ... into memory, on its own dataset. */
static void *gdal_share_run(void *arg)
{
    gdal_share *g = arg;
    GDALDatasetH ds = GDALOpen(g->dem, GA_ReadOnly);
    if (!ds) return g->failed = 1, NULL;
    for (uint32_t t = g->first; t < g->n; t += g->step) {
        GDALDatasetH out = GDALViewshedGenerate(GDALGetRasterBand(ds, 1), "MEM", "", NULL, g->p[t][0], g->p[t][1],
                                                HUB, EYE, 255, 0, 0, 0, 1 - REFRACTION, GVM_Edge, 0, NULL, NULL,
                                                GVOT_NORMAL, NULL);
        if (!out) g->failed = 1;
        else GDALClose(out);
    }
    GDALClose(ds);
    return NULL;
}

/* gdal_viewshed's algorithm in-process over the first n targets on `threads` threads. */
static cost gdal_tracing(const site *st, uint32_t n, unsigned threads)
{
    cost best = {INFINITY, INFINITY};
    for (int rep = 0; rep < repeats; rep++) {
        gdal_share share[64];
        pthread_t tid[64];
        double c0 = cpu_now(), t0 = progress_now();
        for (unsigned k = 0; k < threads; k++) {
            share[k] = (gdal_share){st->dem, (const double(*)[3])st->p, k, threads, n, 0};
            pthread_create(&tid[k], NULL, gdal_share_run, &share[k]);
        }
        int failed = 0;
        for (unsigned k = 0; k < threads; k++) pthread_join(tid[k], NULL), failed |= share[k].failed;
        if (failed) return (cost){-1, 0};
        keep_best(&best, (cost){cpu_now() - c0, progress_now() - t0});
    }
    return best;
}

/* --- the report ----------------------------------------------------------------------------- */

/* One line of both tools' costs; gdal's cpu < 0 when it was not run or failed. */
static void print_pair(const char *what, uint32_t n, unsigned threads, cost s, cost g)
{
    if (s.cpu < 0) {
        printf("  %-24s %3u targets, %u thread%s: sylva failed\n", what, n, threads, threads > 1 ? "s" : "");
        return;
    }
    if (g.cpu < 0) {
        printf("  %-24s %3u targets, %u thread%s: sylva %7.3f s CPU %7.3f s wall | per target CPU sylva %.4f s "
               "| gdal_viewshed not run or failed\n", what, n, threads, threads > 1 ? "s" : " ", s.cpu, s.wall,
               s.cpu / n);
        return;
    }
    printf("  %-24s %3u targets, %u thread%s: sylva %7.3f s CPU %7.3f s wall | gdal %7.3f s CPU %7.3f s wall"
           " | per target CPU sylva %.4f s gdal %.4f s | sylva / gdal CPU %.3f\n",
           what, n, threads, threads > 1 ? "s" : " ", s.cpu, s.wall, g.cpu, g.wall, s.cpu / n, g.cpu / n,
           s.cpu / g.cpu);
}

/* Both tools on one site: whole processes and the tracing alone. The CPU ratios of the goals
 * into ratio_one (1 target, whole process, 1 thread) and ratio_hundred (100 targets, per target),
 * [0] like for like (sylva's raster alone), [1] sylva's every product. */
static int compare_site(site *st, accel *acc, const char *sylva, unsigned threads, int gdal, double ratio_one[2],
                        double ratio_hundred[2], err_buf *err)
{
    double xy[MAX_TARGETS][2], centre[1][2] = {{0, 0}};
    uint32_t dev[MAX_TARGETS] = {0};
    const char *names[1] = {"D"};
    for (uint32_t t = 0; t < MAX_TARGETS; t++) xy[t][0] = st->p[t][0], xy[t][1] = st->p[t][1];
    earth_settings earth = {.curvature = 1, .refraction = REFRACTION, .radius = 6371000};
    ztv_targets tg = {.source = ZTV_TARGETS_GIVEN, .p = st->p, .xy = xy, .development = dev, .n_developments = 1,
                      .names = names, .centre = centre};
    ztv_job job = {.scene = st->s, .accel = acc, .targets = &tg, .observer_height = EYE, .radius = INFINITY,
                   .screened = ZTV_BARE, .earth = &earth, .quiet = 1};
    tg.n = MAX_TARGETS;
    if (ztv_grid_make(st->s, &tg, st->s->terrain->dx, INFINITY, &job.grid, err)) return -1;
    printf("%s: %u x %u nodes of %g m, %.3g cells; observers %g m, targets %g m above the ground; curved Earth, "
           "refraction %g\n", st->name, st->s->terrain->nx, st->s->terrain->ny, st->s->terrain->dx,
           (double)job.grid.nx * job.grid.ny, EYE, HUB, REFRACTION);
    unsigned counts[2] = {1, threads};
    for (int w = 0; w < 2 - (threads == 1); w++) {
        unsigned th = counts[w];
        for (size_t k = 0; k < N_COUNTS; k++) {
            uint32_t n = target_counts[k];
            cost g = gdal ? gdal_processes(st, n, th) : (cost){-1, 0};
            for (int every = 0; every < 2; every++) {
                cost s = sylva_process(st, sylva, n, th, every ? NULL : "raster");
                print_pair(every ? "whole, every product" : "whole, raster (like gdal)", n, th, s, g);
                if (th == 1 && n == 1 && s.cpu > 0 && g.cpu > 0) ratio_one[every] = s.cpu / g.cpu;
                if (th == 1 && n == 100 && s.cpu > 0 && g.cpu > 0) ratio_hundred[every] = s.cpu / g.cpu;
            }
            tg.n = n, job.threads = th;
            ztv_stats stats;
            cost ts = sylva_tracing(&job, &stats, err), tgd = gdal ? gdal_tracing(st, n, th) : (cost){-1, 0};
            print_pair("tracing alone", n, th, ts, tgd);
            printf("  %-24s %3u targets: %.1f %% of the pairs settled by the bare-earth sweep, %.3f rays a pair\n",
                   "", n, stats.pairs ? 100.0 * stats.swept / stats.pairs : 0.0,
                   stats.pairs ? (double)stats.rays / stats.pairs : 0.0);
        }
    }
    return 0;
}

int main(int argc, char **argv)
{
    uint32_t cells = 1000, trees = 100000;
    unsigned threads = 2;
    int gdal = 1, screening_only = 0;
    const char *dem = REAL_DEM, *sylva = SYLVA_BUILD_ROOT "/sylva";
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--no-gdal")) gdal = 0;
        else if (!strcmp(argv[i], "--screening-only")) screening_only = 1;
        else if (i + 1 < argc && !strcmp(argv[i], "--cells")) cells = (uint32_t)atol(argv[++i]);
        else if (i + 1 < argc && !strcmp(argv[i], "--trees")) trees = (uint32_t)atol(argv[++i]);
        else if (i + 1 < argc && !strcmp(argv[i], "--threads")) threads = (unsigned)atol(argv[++i]);
        else if (i + 1 < argc && !strcmp(argv[i], "--dem")) dem = argv[++i];
        else if (i + 1 < argc && !strcmp(argv[i], "--sylva")) sylva = argv[++i];
        else if (i + 1 < argc && !strcmp(argv[i], "--repeats")) repeats = atoi(argv[++i]);
        else {
            fprintf(stderr, "usage: ztv_bench [--cells N] [--trees N] [--threads N] [--dem FILE] [--sylva PATH] "
                            "[--repeats N] [--no-gdal] [--screening-only]\n");
            return 1;
        }
    }
    if (cells < 300 || cells > 20000 || threads < 1 || threads > 64 || repeats < 1)
        return fprintf(stderr, "ztv_bench: --cells 300..20000, --threads 1..64, --repeats 1 or more\n"), 1;
    char cpu[256], dir[] = "/tmp/ztv_bench.XXXXXX";
    bench_cpu_model(cpu, sizeof cpu);
    printf("machine: %s, %ld processors online; %u threads; load average %s\n", cpu,
           sysconf(_SC_NPROCESSORS_ONLN), threads, load_average());
    if (!mkdtemp(dir)) return perror("ztv_bench: mkdtemp"), 3;
    err_buf err = {{0}};
    double ratio_one[2] = {NAN, NAN}, ratio_hundred[2] = {NAN, NAN}, p[2][MAX_TARGETS][3], xy[MAX_TARGETS][2];
    sylva_heightfield *real = screening_only ? NULL : terrain_read(dem);
    if (!real && !screening_only) printf("real DTM %s: not read (the shared data beside the clone?); skipped\n", dem);
    for (int k = real ? 0 : 1; k < 2 - screening_only; k++) {
        site st = {.name = k ? "generated DTM" : "real DTM (Zion SRTM)", .p = p[k]};
        scene *s = build(k ? terrain_new(cells) : real, 0, &err);
        accel acc;
        if (!s || accel_build(&acc, s, threads, &err)) return fprintf(stderr, "ztv_bench: %s\n", err.msg), 4;
        st.s = s;
        targets_place(s, p[k], xy);
        snprintf(st.dir, sizeof st.dir, "%s/%s", dir, k ? "generated" : "real");
        snprintf(st.dem, sizeof st.dem, "%s/dtm.tif", st.dir);
        if (mkdir(st.dir, 0700) || write_terrain(st.dem, s->terrain))
            return fprintf(stderr, "ztv_bench: cannot write %s\n", st.dem), 3;
        double one[2] = {NAN, NAN}, hundred[2] = {NAN, NAN};
        if (compare_site(&st, &acc, sylva, threads, gdal, one, hundred, &err))
            return fprintf(stderr, "ztv_bench: %s\n", err.msg), 4;
        if (k == 0) memcpy(ratio_one, one, sizeof one), memcpy(ratio_hundred, hundred, sizeof hundred);
        accel_free(&acc);
        scene_free(s);
    }

    /* screening: the generated DTM with its forest, 10 targets, tracing alone */
    scene *s = build(terrain_new(cells), trees, &err);
    accel acc;
    if (!s || accel_build(&acc, s, threads, &err)) return fprintf(stderr, "ztv_bench: %s\n", err.msg), 4;
    targets_place(s, p[1], xy);
    double centre[1][2] = {{0, 0}};
    uint32_t dev[MAX_TARGETS] = {0};
    const char *names[1] = {"D"};
    earth_settings earth = {.curvature = 1, .refraction = REFRACTION, .radius = 6371000};
    ztv_targets tg = {.source = ZTV_TARGETS_GIVEN, .n = 10, .p = p[1], .xy = xy, .development = dev,
                      .n_developments = 1, .names = names, .centre = centre};
    ztv_job job = {.scene = s, .accel = &acc, .targets = &tg, .observer_height = EYE, .radius = INFINITY,
                   .screened = ZTV_BARE, .earth = &earth, .threads = threads, .quiet = 1};
    if (ztv_grid_make(s, &tg, s->terrain->dx, INFINITY, &job.grid, &err)) return fprintf(stderr, "ztv_bench: %s\n", err.msg), 4;
    ztv_stats st;
    cost bare = sylva_tracing(&job, &st, &err);
    job.screened = ZTV_VEGETATION;
    cost screened = sylva_tracing(&job, &st, &err);
    if (bare.cpu < 0 || screened.cpu < 0) return fprintf(stderr, "ztv_bench: %s\n", err.msg), 4;
    printf("screening: generated DTM, %u trees, 10 targets, %u threads, tracing alone: bare earth %.3f s CPU "
           "%.3f s wall; bare earth and vegetation %.3f s CPU %.3f s wall: %.2f times bare earth's CPU\n",
           s->n_instances, threads, bare.cpu, bare.wall, screened.cpu, screened.wall, screened.cpu / bare.cpu);
    printf("goals: one target on the real DTM, whole process, 1 thread, sylva / gdal_viewshed CPU: raster alone "
           "(like for like) %.3f, every product %.3f (goal <= 1); 100 targets, per target: raster alone %.3f, every "
           "product %.3f (goal <= 0.2); screened / bare earth CPU %.2f (goal <= 2)\n",
           ratio_one[0], ratio_one[1], ratio_hundred[0], ratio_hundred[1], screened.cpu / bare.cpu);
    accel_free(&acc);
    scene_free(s);
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    printf("peak memory: %.0f MiB; load average at the end %s\n", ru.ru_maxrss / 1024.0, load_average());
    char cmd[160];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    if (system(cmd) != 0) fprintf(stderr, "ztv_bench: could not remove %s\n", dir);
    return 0;
}
