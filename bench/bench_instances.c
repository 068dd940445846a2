/* bench_instances.c — renderer throughput against bare Embree on the same rays and BVH.
 *
 * Builds a fixed scene: a 513 x 513 hilly terrain, one prototype (an icosphere of 20480
 * triangles) and N instances of it (default 100000) scattered over the terrain, sun and
 * Preetham sky. Then:
 *  1. records every ray the path tracer casts for the frame (one thread, not timed);
 *  2. renders the frame on all cores, timed: samples/s and rays/s;
 *  3. replays the recorded rays through rtcIntersect1 / rtcOccluded1 alone on the same BVH on
 *     all cores, timed: rays/s;
 * and prints the renderer's share of raw Embree throughput. Usage:
 *   bench_instances [--instances N] [--size WxH] [--spp N] [--threads N]
 */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include "render/accel.h"
#include "render/render.h"
#include "render/integrator.h"
#include "scene/shapes.h"
#include "util/progress.h"
#include "util/rng.h"

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

static scene *bench_scene(uint32_t n_instances, err_buf *err)
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
    int32_t mat = scene_add_material(s, &green, err);
    mesh *m = mesh_new();
    shape_spec sphere = {.kind = SHAPE_SPHERE, .radius = 3, .subdivisions = 5};
    if (mat < 0 || !m || shape_build(&sphere, mat, m, err)) return NULL;
    s->species = calloc(1, sizeof(species));
    s->species[0] = (species){.name = strdup("ball"), .first_prototype = 0, .n_variants = 1};
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

typedef struct replay_job {
    const accel *acc;
    const recorded_ray *rays;
    size_t begin, end;
    size_t hits;
} replay_job;

static void *replay_worker(void *arg)
{
    replay_job *j = arg;
    struct RTCIntersectContext ic;
    for (size_t i = j->begin; i < j->end; i++) {
        const recorded_ray *q = &j->rays[i];
        rtcInitIntersectContext(&ic);
        if (q->shadow) {
            struct RTCRay r = {.org_x = q->org[0], .org_y = q->org[1], .org_z = q->org[2], .dir_x = q->dir[0],
                               .dir_y = q->dir[1], .dir_z = q->dir[2], .tnear = 0, .tfar = q->tfar, .mask = 0xffffffffu};
            rtcOccluded1(j->acc->top, &ic, &r);
            j->hits += r.tfar < 0;
        } else {
            struct RTCRayHit rh = {.ray = {.org_x = q->org[0], .org_y = q->org[1], .org_z = q->org[2], .dir_x = q->dir[0],
                                           .dir_y = q->dir[1], .dir_z = q->dir[2], .tnear = 0, .tfar = q->tfar,
                                           .mask = 0xffffffffu}};
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(j->acc->top, &ic, &rh);
            j->hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        }
    }
    return NULL;
}

int main(int argc, char **argv)
{
    uint32_t n_inst = 100000, spp = 4, w = 480, h = 270;
    unsigned threads = render_default_threads();
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!strcmp(argv[i], "--instances")) n_inst = (uint32_t)atol(argv[i + 1]);
        else if (!strcmp(argv[i], "--spp")) spp = (uint32_t)atol(argv[i + 1]);
        else if (!strcmp(argv[i], "--threads")) threads = (unsigned)atol(argv[i + 1]);
        else if (!strcmp(argv[i], "--size")) sscanf(argv[i + 1], "%ux%u", &w, &h);
        else {
            fprintf(stderr, "usage: bench_instances [--instances N] [--size WxH] [--spp N] [--threads N]\n");
            return 1;
        }
    }
    err_buf err = {{0}};
    double t0 = progress_now();
    scene *s = bench_scene(n_inst, &err);
    if (!s) {
        fprintf(stderr, "bench: %s\n", err.msg[0] ? err.msg : "out of memory");
        return 4;
    }
    printf("scene: %u instances of a %u-triangle prototype, terrain %ux%u (%u triangles); built in %.2fs\n",
           s->n_instances, s->prototypes[0].mesh->nt, s->terrain->nx, s->terrain->ny,
           2 * (s->terrain->nx - 1) * (s->terrain->ny - 1), progress_now() - t0);
    printf("frame: %ux%u, %u spp, max depth %u, %u threads\n", w, h, spp, s->image.max_depth, threads);

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

    /* 2. the renderer, timed */
    render_stats st;
    ro.recorder = NULL;
    ro.threads = threads;
    f = render_scene(s, &ro, &st, &err);
    if (!f) {
        fprintf(stderr, "bench: %s\n", err.msg);
        return 4;
    }
    film_free(f);
    double renderer_rays = log.n / st.render_seconds;
    printf("renderer:   %.3fs for %llu samples: %.0f samples/s, %.2f Mrays/s (%zu rays, %zu shadow); BVH build %.2fs\n",
           st.render_seconds, (unsigned long long)st.samples, st.samples / st.render_seconds, renderer_rays / 1e6,
           log.n, log.shadow, st.build_seconds);

    /* 3. bare Embree on the same rays and the same BVH */
    accel acc;
    if (accel_build(&acc, s, threads, &err)) {
        fprintf(stderr, "bench: %s\n", err.msg);
        return 4;
    }
    replay_job *jobs = calloc(threads, sizeof *jobs);
    pthread_t *tids = calloc(threads, sizeof *tids);
    double best = 1e30;
    for (int rep = 0; rep < 3; rep++) {
        double r0 = progress_now();
        for (unsigned t = 0; t < threads; t++) {
            jobs[t] = (replay_job){&acc, log.rays, log.n * t / threads, log.n * (t + 1) / threads, 0};
            pthread_create(&tids[t], NULL, replay_worker, &jobs[t]);
        }
        for (unsigned t = 0; t < threads; t++) pthread_join(tids[t], NULL);
        double dt = progress_now() - r0;
        if (dt < best) best = dt;
    }
    double raw_rays = log.n / best;
    printf("raw Embree: %.3fs for the same %zu rays: %.2f Mrays/s (best of 3)\n", best, log.n, raw_rays / 1e6);
    printf("renderer / raw Embree throughput: %.1f %% (goal >= 70 %%)\n", 100.0 * renderer_rays / raw_rays);
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    printf("peak memory: %.0f MiB\n", ru.ru_maxrss / 1024.0);
    accel_free(&acc);
    free(jobs), free(tids), free(log.rays);
    scene_free(s);
    return 0;
}
