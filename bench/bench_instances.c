/* bench_instances.c — renderer throughput against bare Embree on the same rays and BVH.
 *
 * Two fixed scenes on a 513 x 513 hilly terrain with sun and Preetham sky, N instances each
 * (default 100000) scattered over it: "spheres", one opaque prototype (an icosphere of 20480
 * triangles), and "leaf cards", one prototype of 2000 alpha-masked leaf quads (a leaf outline in
 * the texture's alpha, so every hit on a card runs the cut-out test). For each scene:
 *  1. records every ray the path tracer casts for the frame (one thread, not timed);
 *  2. renders the frame, timed: samples/s and rays/s;
 *  3. replays the recorded rays through rtcIntersect1 / rtcOccluded1 alone on the same BVH
 *     (cut-out filters included), timed, scheduled as the renderer schedules its tiles: the
 *     rays, in the order they were cast, cut into as many runs as the frame has 16 x 16 tiles,
 *     one run at a time handed to the threads from one atomic counter;
 *  4. on the leaf cards, replays them again with the cut-out test reading the mesh as it did
 *     before the parts carried their own records (cutout_point_kept: the triangle's number, its
 *     corners, material and uvs, and the texture's alpha), the baseline of the test's cost;
 * renderer and replay runs alternate, three of each, and the best of each is kept; then it
 * prints the renderer's share of raw Embree throughput and the replay's speed with the part's
 * cut-out test against the mesh-reading one. Usage:
 *   bench_instances [--instances N] [--cards N] [--size WxH] [--spp N] [--threads N]
 * (--cards: leaf cards in the crown, 2000 unless given; a crown of a million triangles and more
 * shows the memory waits of the leaf forests.)
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "bench_machine.h"

#include "render/accel.h"
#include "render/render.h"
#include "render/integrator.h"
#include "scene_build/shapes.h"
#include "util/progress.h"
#include "util/rng.h"
#include "util/task_pool.h"

typedef struct recorded_ray {
    float org[3], dir[3], tfar;
    int shadow;
} recorded_ray;

typedef struct ray_log {
    recorded_ray *rays;
    size_t n, cap;
    size_t shadow;
} ray_log;

static void record_ray(void *user, vec3 o, vec3 d, float tfar, int shadow)
{
    ray_log *log = user;
    if (log->n == log->cap) {
        log->cap = log->cap ? log->cap * 2 : 1 << 20;
        log->rays = realloc(log->rays, log->cap * sizeof *log->rays);
        if (!log->rays) {
            fprintf(stderr, "bench: out of memory recording rays\n");
            exit(4);
        }
    }
    log->rays[log->n++] = (recorded_ray){{o.x, o.y, o.z}, {d.x, d.y, d.z}, tfar, shadow};
    log->shadow += shadow;
}

/* n_cards leaf cards (two triangles each, uv over the whole texture) in a crown of radius 3
 * about (0, 0, 3), all in material mat. */
static int leaf_cards(int32_t mat, uint32_t n_cards, mesh *m, err_buf *err)
{
    sylva_rng r;
    rng_stream(&r, 9, "bench leaf cards", 0);
    for (uint32_t k = 0; k < n_cards; k++) {
        vec3 c;
        do c = v3((float)(2 * rng_next_double(&r) - 1), (float)(2 * rng_next_double(&r) - 1),
                  (float)(2 * rng_next_double(&r) - 1));
        while (v3_len(c) > 1);
        c = v3_add(v3_scale(c, 3), v3(0, 0, 3));
        vec3 n = v3_norm(v3((float)(rng_next_double(&r) - 0.5), (float)(rng_next_double(&r) - 0.5), 0.6f));
        vec3 u = v3_norm(v3_cross(n, v3(0, 0, 1))), w = v3_cross(n, u);
        float half = 0.12f;
        float pos[12], uv[8] = {0, 0, 1, 0, 1, 1, 0, 1};
        const float su[4] = {-1, 1, 1, -1}, sw[4] = {-1, -1, 1, 1};
        for (int i = 0; i < 4; i++) {
            vec3 p = v3_add(c, v3_add(v3_scale(u, su[i] * half), v3_scale(w, sw[i] * half)));
            pos[3 * i] = p.x, pos[3 * i + 1] = p.y, pos[3 * i + 2] = p.z;
        }
        const uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
        if (mesh_append(m, pos, NULL, uv, 4, tri, NULL, mat, 2, err)) return -1;
    }
    return 0;
}

/* A leaf outline in alpha: an ellipse filling the texture's middle, opaque green inside. */
static int32_t leaf_texture(scene *s, err_buf *err)
{
    enum { N = 32 };
    uint8_t rgba[N * N * 4];
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            double x = (i + 0.5) / N * 2 - 1, y = (j + 0.5) / N * 2 - 1;
            uint8_t *t = &rgba[(j * N + i) * 4];
            t[0] = 60, t[1] = 130, t[2] = 40, t[3] = x * x / 0.45 + y * y < 1 ? 255 : 0;
        }
    return scene_add_texture(s, "bench leaf", N, N, rgba, err);
}

static scene *bench_scene(uint32_t n_instances, uint32_t cards, err_buf *err)
{
    scene *s = scene_new();
    if (!s) return NULL;
    s->image = (image_settings){.width = 480, .height = 270, .spp = 4, .seed = 1, .max_depth = 4};
    s->camera = (camera_settings){.position = {0, -1100, 260}, .has_look_at = 1, .look_at = {0, 0, 40},
                                  .up = {0, 0, 1}, .fov_deg = 55};
    double az = 220 * M_PI / 180, el = 35 * M_PI / 180;
    s->sun = (sun_settings){.enabled = 1, .direction = {sin(az) * cos(el), cos(az) * cos(el), sin(el)},
                            .irradiance = 1, .color = {1, 1, 1}, .angular_diameter_deg = 0.53};
    s->sky = (sky_settings){.model = SKY_PREETHAM, .turbidity = 3, .scale = 1, .ground_albedo = 0.2};
    /* terrain */
    uint32_t nx = 513;
    sylva_heightfield *hf = calloc(1, sizeof *hf);
    float *z = malloc((size_t)nx * nx * sizeof(float));
    if (!hf || !z) return NULL;
    *hf = (sylva_heightfield){.size = sizeof *hf, .nx = nx, .ny = nx, .x0 = -1000, .y0 = -1000, .dx = 2000.0 / (nx - 1),
                              .dy = 2000.0 / (nx - 1), .z = z, .water_material = -1};
    for (uint32_t j = 0; j < nx; j++)
        for (uint32_t i = 0; i < nx; i++) {
            double x = (double)i / (nx - 1), y = (double)j / (nx - 1);
            z[(size_t)j * nx + i] = (float)(60 * sin(6 * x) * cos(5 * y) + 30 * sin(17 * x + 3 * y));
        }
    s->terrain = hf;
    sylva_material_desc green = {.size = sizeof green, .name = "crown", .bsdf = SYLVA_BSDF_LEAF,
                                 .albedo = {0.1f, 0.25f, 0.06f}, .transmittance = {0.05f, 0.12f, 0.03f}, .texture = -1};
    if (cards && (green.texture = leaf_texture(s, err)) < 0) return NULL;
    green.alpha_mask = cards > 0;
    int32_t mat = scene_add_material(s, &green, err);
    mesh *m = mesh_new();
    shape_spec sphere = {.kind = SHAPE_SPHERE, .radius = 3, .subdivisions = 5};
    if (mat < 0 || !m || (cards ? leaf_cards(mat, cards, m, err) : shape_build(&sphere, mat, m, err))) return NULL;
    s->species = calloc(1, sizeof(species));
    s->species[0] = (species){.name = strdup(cards ? "cards" : "ball"), .first_prototype = 0, .n_variants = 1};
    s->n_species = 1;
    if (scene_add_prototype(s, 0, 0, 1.0, 6, m, err) < 0) return NULL;
    sylva_rng r;
    rng_stream(&r, 42, "bench placement", 0);
    for (uint32_t k = 0; k < n_instances; k++) {
        double p[3] = {-950 + 1900 * rng_next_double(&r), -950 + 1900 * rng_next_double(&r), 0};
        scene_terrain_height(s, p[0], p[1], &p[2]);
        p[2] += 2.5;
        double sc = 0.6 + 0.8 * rng_next_double(&r);
        xform3x4 xf = xf_trs(v3((float)p[0], (float)p[1], (float)p[2]), v3(0, 0, (float)(360 * rng_next_double(&r))),
                             v3((float)sc, (float)sc, (float)(sc * 1.6)));
        if (scene_add_instance(s, 0, &xf, err) < 0) return NULL;
    }
    return s;
}

#define TILE 16 /* the renderer's tile side (render.c) */

/* The cut-out test of the replay's filters: 0, the part's own records (cutout_part_point_kept,
 * as the renderer tests); 1, the mesh read through the part's to_mesh (cutout_point_kept), as
 * the renderer tested before. Set between replays, read by their threads. */
static int replay_reads_mesh;

static void replay_cutout_filter(const struct RTCFilterFunctionNArguments *args)
{
    const geom_info *g = args->geometryUserPtr;
    const unsigned n = args->N;
    const float *hit = (const float *)args->hit; /* RTCHitN: Ng x, y, z, u, v, primID, ... each n long */
    for (unsigned i = 0; i < n; i++) {
        if (args->valid[i] != -1) continue;
        float u = hit[3 * n + i], v = hit[4 * n + i];
        uint32_t prim = ((const uint32_t *)hit)[5 * n + i];
        int kept = replay_reads_mesh ? cutout_point_kept(g->scene, g->mesh, g->part.to_mesh[prim], u, v)
                                     : cutout_part_point_kept(&g->part, prim, u, v);
        if (!kept) args->valid[i] = 0;
    }
}

/* The replay: run t is rays[start[t], start[t + 1]). */
typedef struct replay_job {
    const accel *acc;
    const recorded_ray *rays;
    const size_t *start;
} replay_job;

static void replay_tile(void *ctx, unsigned worker, uint32_t t)
{
    const replay_job *j = ctx;
    struct RTCIntersectContext ic;
    for (size_t i = j->start[t]; i < j->start[t + 1]; i++) {
        const recorded_ray *q = &j->rays[i];
        rtcInitIntersectContext(&ic);
        if (q->shadow) {
            struct RTCRay r = {.org_x = q->org[0], .org_y = q->org[1], .org_z = q->org[2], .dir_x = q->dir[0],
                               .dir_y = q->dir[1], .dir_z = q->dir[2], .tnear = 0, .tfar = q->tfar, .mask = 0xffffffffu};
            rtcOccluded1(j->acc->top, &ic, &r);
        } else {
            struct RTCRayHit rh = {.ray = {.org_x = q->org[0], .org_y = q->org[1], .org_z = q->org[2], .dir_x = q->dir[0],
                                           .dir_y = q->dir[1], .dir_z = q->dir[2], .tnear = 0, .tfar = q->tfar,
                                           .mask = 0xffffffffu}};
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(j->acc->top, &ic, &rh);
        }
    }
}

/* One scene: record, then renderer and replay alternately; prints its figures. Returns 0 or the
 * exit status. */
static int bench_one(uint32_t cards, uint32_t n_inst, uint32_t w, uint32_t h, uint32_t spp, unsigned threads)
{
    err_buf err = {{0}};
    double t0 = progress_now();
    scene *s = bench_scene(n_inst, cards, &err);
    if (!s) {
        fprintf(stderr, "bench: %s\n", err.msg[0] ? err.msg : "out of memory");
        return 4;
    }
    printf("\n%s: %u instances of a %u-triangle prototype%s, terrain %ux%u (%u triangles); built in %.2fs\n",
           cards ? "leaf cards" : "spheres", s->n_instances, s->prototypes[0].mesh->nt,
           cards ? " (alpha-masked leaf quads)" : " (opaque)", s->terrain->nx, s->terrain->ny,
           2 * (s->terrain->nx - 1) * (s->terrain->ny - 1), progress_now() - t0);

    /* 1. record the rays */
    ray_log log = {0};
    ray_recorder rec = {record_ray, &log};
    render_options ro = {.quiet = 1, .spp = spp, .width = w, .height = h, .recorder = &rec};
    film *f = render_scene(s, &ro, NULL, &err);
    if (!f) {
        fprintf(stderr, "bench: %s\n", err.msg);
        return 4;
    }
    film_free(f);

    /* 2 and 3, alternately: the renderer and bare Embree on the same rays and the same BVH */
    ro.recorder = NULL;
    ro.threads = threads;
    render_setup *rs = render_setup_new(s, &ro, &err);
    accel acc;
    if (!rs || accel_build(&acc, s, threads, &err)) {
        fprintf(stderr, "bench: %s\n", err.msg);
        return 4;
    }
    uint32_t runs = ((w + TILE - 1) / TILE) * ((h + TILE - 1) / TILE);
    size_t *start = malloc((runs + 1) * sizeof *start);
    if (!start) return fprintf(stderr, "bench: out of memory\n"), 4;
    for (uint32_t t = 0; t <= runs; t++) start[t] = log.n * t / runs;
    replay_job job = {&acc, log.rays, start};
    if (cards) { /* the replay's cut-out filters, which can read the mesh as before */
        RTCGeometry leaves = rtcGetGeometry(acc.proto_scenes[0], ACCEL_PART_CUTOUT);
        rtcSetGeometryIntersectFilterFunction(leaves, replay_cutout_filter);
        rtcSetGeometryOccludedFilterFunction(leaves, replay_cutout_filter);
        rtcCommitGeometry(leaves);
        rtcCommitScene(acc.proto_scenes[0]);
        rtcCommitScene(acc.top);
    }
    double best_render = 1e30, best_raw = 1e30, best_mesh = 1e30;
    render_stats st = {0};
    for (int rep = 0; rep < 3; rep++) {
        render_stats one;
        f = render_setup_run(rs, &ro, &one, &err);
        if (!f) {
            fprintf(stderr, "bench: %s\n", err.msg);
            return 4;
        }
        film_free(f);
        if (one.render_seconds < best_render) best_render = one.render_seconds, st = one;
        double r0 = progress_now();
        task_pool_run(threads, runs, replay_tile, &job);
        double dt = progress_now() - r0;
        if (dt < best_raw) best_raw = dt;
        if (!cards) continue;
        replay_reads_mesh = 1;
        r0 = progress_now();
        task_pool_run(threads, runs, replay_tile, &job);
        dt = progress_now() - r0;
        replay_reads_mesh = 0;
        if (dt < best_mesh) best_mesh = dt;
    }
    double renderer_rays = log.n / best_render, raw_rays = log.n / best_raw;
    printf("renderer:   %.3fs for %llu samples: %.0f samples/s, %.2f Mrays/s (%zu rays, %zu shadow); setup %.2fs "
           "(BVH %.2fs)\n", best_render, (unsigned long long)st.samples, st.samples / best_render, renderer_rays / 1e6,
           log.n, log.shadow, st.build_seconds, st.bvh_seconds);
    printf("raw Embree: %.3fs for the same %zu rays in %u runs handed out as tiles: %.2f Mrays/s\n", best_raw, log.n,
           runs, raw_rays / 1e6);
    printf("renderer / raw Embree throughput: %.1f %% (goal >= 70 %%); best of 3 each, alternating\n",
           100.0 * renderer_rays / raw_rays);
    if (cards)
        printf("cut-out test: the replay takes %.3fs with the parts' own records, %.3fs reading the mesh as "
               "before: %.2fx the rays/s (best of 3 each, alternating)\n", best_raw, best_mesh, best_mesh / best_raw);
    accel_free(&acc);
    render_setup_free(rs);
    free(start), free(log.rays);
    scene_free(s);
    return 0;
}

int main(int argc, char **argv)
{
    uint32_t n_inst = 100000, spp = 4, w = 480, h = 270, cards = 2000;
    unsigned threads = render_default_threads();
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!strcmp(argv[i], "--instances")) n_inst = (uint32_t)atol(argv[i + 1]);
        else if (!strcmp(argv[i], "--spp")) spp = (uint32_t)atol(argv[i + 1]);
        else if (!strcmp(argv[i], "--cards") && atol(argv[i + 1]) > 0) cards = (uint32_t)atol(argv[i + 1]);
        else if (!strcmp(argv[i], "--threads")) threads = (unsigned)atol(argv[i + 1]);
        else if (!strcmp(argv[i], "--size")) sscanf(argv[i + 1], "%ux%u", &w, &h);
        else {
            fprintf(stderr, "usage: bench_instances [--instances N] [--cards N] [--size WxH] [--spp N] [--threads N]\n");
            return 1;
        }
    }
    char cpu[256];
    bench_cpu_model(cpu, sizeof cpu);
    double load[1] = {-1};
    getloadavg(load, 1);
    printf("machine: %s, %ld processors online, load average %.2f\n", cpu, sysconf(_SC_NPROCESSORS_ONLN), load[0]);
    printf("frame: %ux%u, %u spp, max depth 4, %u threads\n", w, h, spp, threads);
    int rc = bench_one(0, n_inst, w, h, spp, threads);
    if (!rc) rc = bench_one(cards, n_inst, w, h, spp, threads);
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    printf("peak memory: %.0f MiB\n", ru.ru_maxrss / 1024.0);
    return rc;
}
